#include "brush_setup.h"
#include "commands.h"
#include "finite_arguments.h"
#include "json_output.h"
#include "object_choice.h"
#include "output_rules.h"
#include "progress_line.h"
#include "sculpt_session.h"
#include "stroke_script.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gpu_document.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace octaclay::app {
namespace {

[[noreturn]] void badArgument(const std::string& message) {
  throw core::Error(core::ErrorKind::InvalidArgument, message);
}

// what names the option in messages ("--view", "--param amount").
std::vector<float> numbers(const std::string& text, char separator, const std::string& what) {
  std::vector<float> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, separator)) {
    std::size_t used = 0;
    float v = 0;
    try {
      v = std::stof(item, &used);
    } catch (const std::out_of_range&) {
      if (std::isfinite(std::strtod(item.c_str(), nullptr)))
        badArgument(what + ": '" + item +
                    "' is outside what a float holds (magnitudes up to 3.4e38)");
      used = 0;
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size()) badArgument(what + ": '" + item + "' is not a number");
    if (!std::isfinite(v)) badArgument(what + ": '" + item + "' is not a finite number");
    values.push_back(v);
  }
  return values;
}

std::vector<std::array<float, 2>> parsePath(const std::string& text) {
  std::vector<std::array<float, 2>> path;
  std::stringstream in(text);
  std::string pair;
  while (std::getline(in, pair, ';')) {
    const std::vector<float> uv = numbers(pair, ',', "--path");
    if (uv.size() != 2) badArgument("--path: '" + pair + "' is not a u,v pair");
    path.push_back({uv[0], uv[1]});
  }
  if (path.empty()) badArgument("--path needs at least one u,v pair");
  return path;
}

std::array<float, 4> parseParameter(const gpu::BrushManifest& brush, const std::string& id,
                                    const std::string& text) {
  const gpu::BrushParameter* p = brush.parameter(id);
  if (!p) {
    std::string known;
    for (const auto& q : brush.parameters)
      known += (known.empty() ? "" : ", ") + q.id;
    badArgument("brush " + brush.id + " has no parameter '" + id + "'" +
                (known.empty() ? " (it has none)" : " (it has: " + known + ")"));
  }
  std::array<float, 4> v{};
  switch (p->type) {
  case gpu::ParameterType::Bool:
    if (text == "true" || text == "1" || text == "on")
      v[0] = 1;
    else if (text != "false" && text != "0" && text != "off")
      badArgument("--param " + id + ": '" + text + "' is not true or false");
    return v;
  case gpu::ParameterType::Enum: {
    const auto at = std::find(p->options.begin(), p->options.end(), text);
    if (at == p->options.end()) badArgument("--param " + id + ": '" + text + "' is not an option");
    v[0] = static_cast<float>(at - p->options.begin());
    return v;
  }
  case gpu::ParameterType::Color: {
    const std::vector<float> c = numbers(text, ',', "--param " + id);
    if (c.size() != 3 && c.size() != 4) badArgument("--param " + id + ": give r,g,b or r,g,b,a");
    for (std::size_t k = 0; k < c.size(); ++k)
      v[k] = c[k];
    if (c.size() == 3) v[3] = 1;
    return v;
  }
  case gpu::ParameterType::Material: // resolved against the loaded materials later
    return v;
  case gpu::ParameterType::Float:
  case gpu::ParameterType::Int:
    v[0] = numbers(text, ',', "--param " + id).at(0);
    if (v[0] < p->min || v[0] > p->max)
      badArgument("--param " + id + " = " + text + " is outside [" + std::to_string(p->min) + ", " +
                  std::to_string(p->max) + "]");
    return v;
  }
  return v;
}

// Uploads the materials when the brush has a material parameter, and turns --param
// material=<id> into the engine's index for that material.
void loadMaterialsFor(const gpu::BrushManifest& brush, gpu::BrushEngine& engine,
                      std::map<std::string, std::array<float, 4>>& parameters,
                      const std::vector<std::string>& given) {
  const bool needed = std::any_of(brush.parameters.begin(), brush.parameters.end(),
                                  [](auto& p) { return p.type == gpu::ParameterType::Material; });
  if (!needed) return;
  const gpu::MaterialCatalog catalog = scanMaterials();
  for (const std::string& e : catalog.errors())
    std::cerr << "octaclay-cli: skipped a material: " << e << "\n";
  engine.setMaterials(catalog);
  for (const gpu::BrushParameter& p : brush.parameters) {
    if (p.type != gpu::ParameterType::Material) continue;
    std::string id = p.options.front();
    for (const std::string& g : given)
      if (g.rfind(p.id + "=", 0) == 0) id = g.substr(p.id.size() + 1);
    const int index = engine.materialIndex(id);
    if (index < 0) {
      std::string known;
      for (const std::string& m : engine.materialIds())
        known += (known.empty() ? "" : ", ") + m;
      badArgument("--param " + p.id + ": no material '" + id +
                  "' (installed: " + (known.empty() ? "none" : known) + ")");
    }
    parameters[p.id] = {static_cast<float>(index), 0, 0, 0};
  }
}

unsigned parseSymmetry(const std::string& text) {
  unsigned axes = gpu::kSymmetryNone;
  for (char c : text) {
    if (c == 'x')
      axes |= gpu::kSymmetryX;
    else if (c == 'y')
      axes |= gpu::kSymmetryY;
    else if (c == 'z')
      axes |= gpu::kSymmetryZ;
    else if (c != ',')
      badArgument("--symmetry takes x, y and/or z, e.g. x or x,z");
  }
  return axes;
}

} // namespace

Command addStrokeCommand(CLI::App& app) {
  struct Options {
    std::string input, output, brush, path, symmetry, view, drag, keepDetail = "on", object;
    std::vector<std::string> params;
    float radius = 0.1f, strength = 0.5f, spacing = 0;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub =
      app.add_subcommand("stroke", "Apply a brush stroke along a path of (u, v) points");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  addObjectOption(*sub, opt->object);
  sub->add_option("--brush", opt->brush, "Brush id (see `octaclay-cli brushes`)")->required();
  sub->add_option("--param", opt->params, "Brush parameter id=value (repeatable)");
  sub->add_option("--path", opt->path,
                  "u,v[;u,v...] in [0, 1]: one pair is one dab; for a dragging brush (grab, "
                  "snake-hook) the first point is where the drag starts and the last where it ends")
      ->required();
  sub->add_option("--radius", opt->radius, "Fraction of the bounding-box diagonal")
      ->check(kFiniteNumber)
      ->capture_default_str();
  sub->add_option("--strength", opt->strength,
                  "How far the stroke moves the surface per radius travelled, as a fraction of the "
                  "radius (a sculpt brush's dab applies strength × spacing; paint and splats "
                  "apply it whole); negative pulls")
      ->check(kFiniteNumber)
      ->capture_default_str();
  sub->add_option("--spacing", opt->spacing,
                  "Between dabs, along the surface as the stroke began, as a fraction of the "
                  "radius, 0.01 to 100 (default: the brush's, 0.15 for the built-ins)")
      ->check(kFiniteNumber);
  sub->add_option("--symmetry", opt->symmetry, "Mirror planes through the model's centre: x, y, z");
  sub->add_option("--view", opt->view,
                  "Camera eye x,y,z: splats project from it through each dab's centre, and a "
                  "drag (grab, snake-hook) moves in the view plane through its start "
                  "(default: splats along the centre normal, drags along the path)");
  sub->add_option("--drag", opt->drag,
                  "x,y,z[;x,y,z...]: for a dragging brush (grab, snake-hook), object-space points "
                  "the drag moves through after the path, as a pointer off the surface would "
                  "(projected into the view plane with --view)");
  sub->add_option("--keep-detail", opt->keepDetail,
                  "on: relax what the stroke stretched so it keeps its share of samples "
                  "(one step with the stroke); off: leave the samples where the brush put them")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  sub->add_option("-o,--output", opt->output, "Document to write (.exr)")->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {
      sub, [opt, sub]() {
        requireOutputExtension(opt->output, {".exr"}, "the document");
        requireFinite(opt->strength, "--strength");
        requireFinite(opt->spacing, "--spacing");
        // Given, the spacing is the user's: never silently the default or a clamp.
        if (sub->count("--spacing") > 0 && !(opt->spacing >= 0.01f && opt->spacing <= 100))
          badArgument("--spacing " + sub->get_option("--spacing")->as<std::string>() +
                      " is outside 0.01 to 100 (a fraction of the radius between dabs; leave it "
                      "out for the brush's own)");
        if (!(opt->radius > 0 && opt->radius <= 1))
          badArgument("--radius must be in (0, 1] (a fraction of the bounding-box diagonal)");
        const std::vector<std::array<float, 2>> path = parsePath(opt->path);
        const gpu::BrushCatalog catalog = scanBrushes();
        const gpu::BrushManifest* brush = catalog.find(opt->brush);
        if (!brush) {
          // A brush folder of that name that failed to load: say why, not just "no brush".
          for (const gpu::BrushCatalogError& e : catalog.errors())
            if (e.path.parent_path().filename() == opt->brush || e.path.filename() == opt->brush)
              throw gpu::BrushLoadError(e.message);
          std::string known;
          for (const auto& b : catalog.brushes())
            known += (known.empty() ? "" : ", ") + b.id;
          badArgument("no brush '" + opt->brush + "' (loaded: " + known + ")");
        }
        // The stroke as the modeller's Brushes panel would set it: the brush's own area and
        // falloff, the radius a fraction of the diagonal, pressure 1.
        StrokeScript script;
        StrokeStart& start = script.start;
        start.brushId = brush->id;
        start.settings.brushId = brush->id;
        start.settings.radius = opt->radius;
        start.settings.strength = opt->strength;
        start.settings.area = brush->area;
        start.settings.falloff = brush->falloff;
        start.settings.symmetry = parseSymmetry(opt->symmetry);
        start.settings.keepDetail = opt->keepDetail == "on";
        start.spacing = opt->spacing;
        // A script's points stay on their surface points, so a script that dabs there again
        // (a limb pulled by repeated clicks) finds the same spot after the relaxation.
        script.path = path;
        for (const std::string& p : opt->params) {
          const auto eq = p.find('=');
          if (eq == std::string::npos) badArgument("--param '" + p + "' is not id=value");
          start.settings.parameters[p.substr(0, eq)] =
              parseParameter(*brush, p.substr(0, eq), p.substr(eq + 1));
        }

        if (!opt->drag.empty()) {
          std::stringstream in(opt->drag);
          for (std::string point; std::getline(in, point, ';');) {
            const std::vector<float> xyz = numbers(point, ',', "--drag");
            if (xyz.size() != 3) badArgument("--drag: '" + point + "' is not an x,y,z point");
            script.dragPoints.push_back({xyz[0], xyz[1], xyz[2]});
          }
        }

        if (!opt->view.empty()) {
          const std::vector<float> eye = numbers(opt->view, ',', "--view");
          if (eye.size() != 3) badArgument("--view takes the camera eye as x,y,z");
          start.eye = core::Vec3f{eye[0], eye[1], eye[2]};
        }

        ProgressLine progress("stroke", !opt->json);
        progress.stage("reading");
        ChosenObject chosen = readChosenObject(opt->input, opt->object);
        requireUnlocked(chosen, "sculpt");
        core::Document document = std::move(chosen.object().document);
        core::requireUsableSize(document.positions, "cannot sculpt " + opt->input);
        const gpu::GlContext context = gpu::GlContext::createHeadless();
        gpu::BrushEngine engine;
        loadMaterialsFor(*brush, engine, start.settings.parameters, opt->params);
        // The modeller's door (SculptSession): the stroke shares --strength out by spacing.
        SculptSession session;
        session.setBrushes(engine, catalog);
        session.loadBrush(*brush);
        session.setDocument(std::move(document));
        progress.stage("stroking");
        const StrokeEnd result = playStroke(session, script, [&progress](int done, int expected) {
          progress.count("dabs", done, expected);
        });
        const double perDab = result.dabs ? result.engineMs / result.dabs : 0.0;
        // The dabs after the first move: what a long stroke costs per dab, without what the
        // first dab pays once (programs compiled, scratch textures made).
        const int laterDabs = result.dabs - result.firstMoveDabs;
        const double sustained =
            laterDabs > 0 ? (result.engineMs - result.firstMoveMs) / laterDabs : perDab;
        std::ostringstream report; // made before the save, which commits last
        if (opt->json)
          report << app::JsonReply{{"output", opt->output},
                                   {"brush", brush->id},
                                   {"dabs", result.dabs},
                                   {"engine_ms", result.engineMs},
                                   {"ms_per_dab", perDab},
                                   {"first_dab_ms", result.firstMoveMs},
                                   {"sustained_ms_per_dab", sustained},
                                   {"phases_ms",
                                    {{"centre", result.phases.centreMs},
                                     {"reach", result.phases.reachMs},
                                     {"undo", result.phases.undoMs},
                                     {"passes", result.phases.passesMs}}},
                                   {"changed_tiles", result.changedTiles},
                                   {"undo_bytes", result.stepBytes}}
                        .dump()
                 << "\n";
        else
          report << "stroke " << brush->id << ": " << result.dabs << " dabs in " << result.engineMs
                 << " ms (" << perDab << " ms per dab), wrote " << opt->output << "\n";
        progress.stage("writing");
        writeChosenObject(chosen, session.document(), opt->output);
        std::cout << report.str();
        return kExitOk;
      }};
}

} // namespace octaclay::app
