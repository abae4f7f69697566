// octaclay-cli compress / decompress (issue 8): a document to the .ocz container and back,
// with the size and error figures of the chosen codec, and `compress --sweep`, the
// rate–distortion report of every codec beside Draco.

#include "commands.h"
#include "finite_arguments.h"
#include "json_output.h"
#include "object_choice.h"
#include "output_rules.h"
#include "progress_line.h"
#include "rd_measure.h"

#include "octaclay/core/codec/compressed_document.h"
#include "octaclay/core/codec/compressed_scene.h"
#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/file_extension.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace octaclay::app {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string codecList() {
  std::string list;
  for (const core::Codec& c : core::codecs())
    list += (list.empty() ? "" : ", ") + std::string(c.info.id);
  return list;
}

const core::Codec& requireCodec(const std::string& id) {
  const core::Codec* codec = core::findCodec(std::string_view(id));
  if (codec == nullptr)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "unknown codec '" + id + "'; the codecs are " + codecList());
  return *codec;
}

std::vector<std::uint8_t> readBytes(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw core::Error(core::ErrorKind::Io, path + ": no such file");
  std::ifstream file(path, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                  std::istreambuf_iterator<char>());
  if (file.bad()) throw core::Error(core::ErrorKind::Io, path + ": cannot be read");
  return bytes;
}

nlohmann::json finiteOrNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

struct CompressOptionsCli {
  std::string input, output, codec, mode, object;
  double quality = -1; // < 0: the codec's default
  bool json = false, sweep = false, noReport = false;
  std::size_t samples = 0;
};

std::string sweepReport(const CompressOptionsCli& opt, const core::Document& doc,
                        std::span<const RdPoint> points, const std::string& title,
                        const std::vector<std::filesystem::path>& paths) {
  std::ostringstream out;
  if (opt.json) {
    nlohmann::json rows = nlohmann::json::array();
    for (const RdPoint& p : points)
      rows.push_back({{"codec", p.codec},
                      {"setting", p.setting},
                      {"bytes", p.bytes},
                      {"bits_per_vertex", p.bitsPerVertex},
                      {"psnr", finiteOrNull(p.distortion.psnr)},
                      {"normal_angle_deg", p.distortion.normalAngleDeg},
                      {"max_seam_gap", p.distortion.maxSeamGap},
                      {"exact", p.exact}});
    out << app::JsonReply{{"input", opt.input},
                          {"n", doc.size()},
                          {"markdown", paths[0].string()},
                          {"csv", paths[1].string()},
                          {"plot", paths[2].string()},
                          {"points", rows}}
               .dump()
        << "\n";
  } else {
    out << rdMarkdown(points, title) << "\nwrote " << paths[0].string() << ", " << paths[1].string()
        << ", " << paths[2].string() << "\n";
  }
  return out.str();
}

int runSweep(const CompressOptionsCli& opt) {
  const std::string directory =
      opt.output.empty() ? std::filesystem::path(opt.input).stem().string() + "-rd" : opt.output;
  const core::Document doc =
      std::move(readChosenObject(opt.input, opt.object, {.layers = false}).object().document);
  core::requireOctahedral(doc.positions, "compress", opt.input);
  const RdReference reference = makeRdReference(doc.positions);
  const std::vector<RdPoint> points = sweep(reference, opt.samples);
  const std::string title =
      "Rate-distortion: " + std::filesystem::path(opt.input).filename().string() +
      ", N = " + std::to_string(doc.size());
  // A report folder this run creates goes again when the report fails.
  std::error_code ec;
  const bool created = std::filesystem::create_directories(directory, ec);
  if (ec || !std::filesystem::is_directory(directory))
    throw core::Error(core::ErrorKind::Io, "cannot write the report to " + directory + ": " +
                                               (ec ? ec.message() : "it is not a folder"));
  try {
    core::OutputSet set;
    const auto paths = stageRdReport(points, title, directory, set);
    const std::string report = sweepReport(opt, doc, points, title, paths);
    set.commit();
    std::cout << report;
  } catch (...) {
    if (created) std::filesystem::remove(directory, ec);
    throw;
  }
  return kExitOk;
}

// A scene (several objects, or one with a name, place, lock or a torus or plane image): every
// object in one .ocz (version 2), each object's exactness and largest coordinate error reported.
int runCompressScene(const CompressOptionsCli& opt, const core::Scene& scene,
                     ProgressLine& progress) {
  for (const core::SceneObject& object : scene.objects)
    core::requireUsableSize(object.document.positions,
                            opt.input + " (object '" + object.name + "')");
  progress.stage("encoding");
  core::CompressOptions options;
  options.codec = opt.codec;
  options.params.quality = opt.quality;
  options.params.mode = opt.mode;
  auto start = Clock::now();
  const std::vector<std::uint8_t> bytes = core::compressScene(scene, options);
  const double encodeMs = millisecondsSince(start);
  progress.stage("decoding");
  start = Clock::now();
  const core::Scene decoded = core::decompressScene(bytes);
  const double decodeMs = millisecondsSince(start);

  nlohmann::json objects = nlohmann::json::array();
  std::size_t samples = 0;
  bool exact = true;
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const auto& original = scene.objects[k].document.positions.texels();
    const auto& back = decoded.objects[k].document.positions.texels();
    double error = 0;
    for (std::size_t t = 0; t < original.size(); ++t)
      for (const float d :
           {original[t].x - back[t].x, original[t].y - back[t].y, original[t].z - back[t].z})
        error = std::max(error, double(std::abs(d)));
    samples += original.size();
    exact = exact && error == 0;
    const core::GeometryImage& image = scene.objects[k].document.positions;
    objects.push_back({{"name", scene.objects[k].name},
                       {"topology", std::string(core::topologyName(image.topology()))},
                       {"width", image.width()},
                       {"height", image.height()},
                       {"exact", error == 0},
                       {"max_error", error}});
  }
  const core::Codec& codec = requireCodec(opt.codec);
  const double bitsPerSample = 8.0 * double(bytes.size()) / double(samples);
  nlohmann::json out{{"input", opt.input},    {"output", opt.output},
                     {"codec", opt.codec},    {"lossy", codec.info.lossy},
                     {"bytes", bytes.size()}, {"bits_per_vertex", bitsPerSample},
                     {"encode_ms", encodeMs}, {"decode_ms", decodeMs},
                     {"exact", exact},        {"objects", objects}};
  if (codec.info.lossy) out["quality"] = opt.quality >= 0 ? opt.quality : codec.info.defaultQuality;
  if (!opt.mode.empty()) out["mode"] = opt.mode;
  std::ostringstream report; // made before the file is committed
  if (opt.json) {
    report << jsonText(out) << "\n";
  } else {
    report << opt.output << ": " << scene.objects.size() << " objects, " << bytes.size()
           << " bytes, " << bitsPerSample << " bits per vertex (" << opt.codec << ")\nencode "
           << encodeMs << " ms, decode " << decodeMs << " ms\n";
    for (const nlohmann::json& object : objects)
      report << "  " << object["name"].get<std::string>() << ": "
             << (object["exact"].get<bool>()
                     ? std::string("positions exact")
                     : "largest coordinate error " + object["max_error"].dump())
             << "\n";
  }
  core::writeBytesAtomically(opt.output, bytes);
  std::cout << report.str();
  return kExitOk;
}

int runCompress(const CompressOptionsCli& opt) {
  if (opt.sweep) return runSweep(opt);
  if (opt.codec.empty())
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "compress needs --codec (one of " + codecList() + ") or --sweep");
  if (opt.output.empty())
    throw core::Error(core::ErrorKind::InvalidArgument, "compress needs -o doc.ocz");
  const core::Codec& codec = requireCodec(opt.codec);
  if (!opt.mode.empty() && codec.info.id != "exr")
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "--mode is an exr option; " + opt.codec + " has no modes");
  if (opt.quality != -1 && !(opt.quality >= 0))
    throw core::Error(core::ErrorKind::InvalidArgument, "--quality must be a number >= 0 (" +
                                                            std::string(codec.info.id) + ": " +
                                                            std::string(codec.info.quality) + ")");
  requireOutputExtension(opt.output, {".ocz"}, "the compressed document");
  requireNotInput(opt.output, opt.input);

  ProgressLine progress("compress", !opt.json);
  progress.stage("reading");
  // Without --object, a scene (not a plain octahedral document) goes whole into the .ocz.
  if (opt.object.empty()) {
    core::Scene scene = core::readScene(opt.input);
    if (!isPlainDocument(scene, opt.input) ||
        scene.objects.front().document.topology != core::Topology::Octahedral)
      return runCompressScene(opt, scene, progress);
  }
  ChosenObject chosen = readChosenObject(opt.input, opt.object);
  // A torus or plane named with --object goes alone into a scene .ocz (with its name, place and
  // topology): the one-document container holds only the ball.
  if (chosen.object().document.topology != core::Topology::Octahedral) {
    core::Scene one;
    one.objects.push_back(chosen.object());
    return runCompressScene(opt, one, progress);
  }
  const core::Document doc = std::move(chosen.scene.objects[chosen.index].document);
  core::requireUsableSize(doc.positions, opt.input);
  progress.stage("encoding");
  core::CompressOptions options;
  options.codec = opt.codec;
  options.params.quality = opt.quality;
  options.params.mode = opt.mode;
  auto start = Clock::now();
  std::vector<std::uint8_t> bytes;
  try {
    bytes = core::compressDocument(doc, options);
  } catch (const core::Error& e) {
    // With no --quality or --mode the codec's defaults failed: the document is at fault, not
    // an argument the user gave.
    if (opt.quality != -1 || !opt.mode.empty() || e.kind() != core::ErrorKind::InvalidArgument)
      throw;
    const std::string why = e.what();
    const bool precision = why.find("float precision") != std::string::npos;
    throw core::Error(core::ErrorKind::InvalidInput,
                      opt.input + ": " + opt.codec + " cannot code this document at its defaults" +
                          (precision ? " (its coordinates are too large for float precision "
                                       "at its size: move it near the origin or scale it down)"
                                     : std::string()) +
                          ": " + why);
  }
  const double encodeMs = millisecondsSince(start);
  progress.stage("decoding");
  start = Clock::now();
  const core::Document decoded = core::decompressDocument(bytes);
  const double decodeMs = millisecondsSince(start);

  const bool exact =
      std::equal(doc.positions.texels().begin(), doc.positions.texels().end(),
                 decoded.positions.texels().begin(), decoded.positions.texels().end());
  const double quality = opt.quality >= 0 ? opt.quality : codec.info.defaultQuality;
  nlohmann::json out{{"input", opt.input},
                     {"output", opt.output},
                     {"codec", opt.codec},
                     {"lossy", codec.info.lossy},
                     {"n", doc.size()},
                     {"bytes", bytes.size()},
                     {"bits_per_vertex", bitsPerVertex(bytes.size(), doc.size())},
                     {"encode_ms", encodeMs},
                     {"decode_ms", decodeMs},
                     {"exact", exact}};
  if (codec.info.lossy) out["quality"] = quality;
  if (!opt.mode.empty()) out["mode"] = opt.mode;
  if (!exact && opt.noReport) {
    out["report"] = nullptr;
  } else if (!exact) {
    progress.stage("measuring");
    const Distortion d =
        measureDistortion(makeRdReference(doc.positions), decoded.positions, opt.samples);
    out["psnr"] = finiteOrNull(d.psnr);
    out["rms"] = d.rms;
    out["hausdorff"] = d.hausdorff;
    out["normal_angle_deg"] = d.normalAngleDeg;
    out["max_seam_gap"] = d.maxSeamGap;
    out["report"] = {{"method", "sampled"},
                     {"samples", d.samples},
                     {"stride", d.stride},
                     {"leaves_per_query", core::SurfaceDistanceOptions{}.leavesPerQuery},
                     {"leaf_budget", core::SurfaceDistanceOptions{}.leafBudget},
                     {"bounded_queries", d.boundedQueries},
                     {"exact", d.boundedQueries == 0}};
  }
  // Measured and reported before the file is committed: a failure leaves the previous one.
  std::ostringstream report;
  if (opt.json) {
    report << jsonText(out) << "\n";
    core::writeBytesAtomically(opt.output, bytes);
    std::cout << report.str();
    return kExitOk;
  }
  report << opt.output << ": " << bytes.size() << " bytes, " << out["bits_per_vertex"].get<double>()
         << " bits per vertex (" << opt.codec << ")\nencode " << encodeMs << " ms, decode "
         << decodeMs << " ms\n";
  if (exact)
    report << "positions exact\n";
  else if (opt.noReport)
    report << "lossy; no error report (--no-report)\n";
  else
    report << "PSNR " << out["psnr"].dump() << " dB, RMS " << out["rms"].get<double>()
           << ", Hausdorff " << out["hausdorff"].get<double>() << " of the diagonal\n"
           << "mean normal angle " << out["normal_angle_deg"].get<double>() << " deg, max seam gap "
           << out["max_seam_gap"].get<double>() << "\n";
  core::writeBytesAtomically(opt.output, bytes);
  std::cout << report.str();
  return kExitOk;
}

} // namespace

Command addCompressCommand(CLI::App& app) {
  auto opt = std::make_shared<CompressOptionsCli>();
  CLI::App* sub = app.add_subcommand(
      "compress", "Store a document compressed (.ocz): every object of a scene, or the one "
                  "--object names; or with --sweep write the rate-distortion report of every "
                  "codec beside Draco");
  sub->add_option("document", opt->input, "Document (.exr)")->required();
  addObjectOption(*sub, opt->object);
  sub->add_option("--codec", opt->codec,
                  "Positions codec: bytepack, dct, exr, wavelet or lossless");
  sub->add_option("--quality", opt->quality,
                  "Codec quality: bytepack regions per side R (a power of two), dct 1-100, wavelet "
                  "error bound (fraction of the diagonal); default: the codec's")
      ->check(kFiniteNumber);
  sub->add_option("--mode", opt->mode, "exr only: zip, piz, pxr24 or half");
  sub->add_option("-o,--output", opt->output,
                  "Compressed document (.ocz); with --sweep the report folder");
  sub->add_flag("--sweep", opt->sweep,
                "Rate-distortion report: rd.md, rd.csv and rd.png for every codec and quality");
  sub->add_option("--samples", opt->samples,
                  "Random points per surface for the error, besides the vertices")
      ->capture_default_str();
  sub->add_flag("--no-report", opt->noReport,
                "Skip the error figures of a lossy codec (PSNR, RMS, Hausdorff, normals)");
  sub->add_flag("--json", opt->json, "Print one JSON object");
  return {sub, [opt]() { return runCompress(*opt); }};
}

Command addDecompressCommand(CLI::App& app) {
  struct Options {
    std::string input, output;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub =
      app.add_subcommand("decompress", "Turn a compressed document (.ocz) back into .exr");
  sub->add_option("compressed", opt->input, "Compressed document (.ocz)")->required();
  sub->add_option("-o,--output", opt->output, "Document to write (.exr)")->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");
  return {sub, [opt]() {
            requireOutputExtension(opt->output, {".exr"}, "the document");
            requireNotInput(opt->output, opt->input);
            const std::vector<std::uint8_t> bytes = readBytes(opt->input);
            const auto start = Clock::now();
            // A version-1 file's one object is named as the output's plain document reads, so
            // it is written as the plain document it was.
            const std::string stem = std::filesystem::path(opt->output).stem().string();
            const core::Scene scene = [&] {
              try {
                return core::decompressScene(bytes, core::objectNameProblem(stem) ? "Model" : stem);
              } catch (const core::Error& e) {
                if (e.kind() != core::ErrorKind::InvalidInput) throw;
                throw core::Error(e.kind(), opt->input + ": " + e.what());
              }
            }();
            const double decodeMs = millisecondsSince(start);
            const int n = scene.objects.front().document.size();
            std::ostringstream report; // made before the save, which commits last
            if (opt->json)
              report << app::JsonReply{{"input", opt->input},
                                       {"output", opt->output},
                                       {"n", n},
                                       {"objects", scene.objects.size()},
                                       {"bytes", bytes.size()},
                                       {"decode_ms", decodeMs}}
                            .dump()
                     << "\n";
            else if (scene.objects.size() == 1)
              report << opt->output << ": N = " << n << ", decoded in " << decodeMs << " ms\n";
            else
              report << opt->output << ": " << scene.objects.size() << " objects, decoded in "
                     << decodeMs << " ms\n";
            writeSceneOrDocument(scene, opt->output, opt->output);
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
