#include "brush_setup.h"
#include "commands.h"
#include "json_output.h"

#include "octaclay/gpu/brush_library.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <optional>

namespace octaclay::app {

Command addBrushesCommand(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  CLI::App* sub = app.add_subcommand("brushes", "List every brush found on the plugin path, "
                                                "with its parameters and any load errors");
  sub->add_flag("--json", *json, "Print one JSON object");
  return {sub, [json]() {
            // Compiling needs GL; without it the manifests are still listed and checked.
            std::optional<gpu::GlContext> context;
            std::optional<gpu::BrushLibrary> library;
            std::vector<std::string> problems;
            try {
              context.emplace(gpu::GlContext::createHeadless());
              library.emplace(gpu::BrushCatalog::defaultSearchPath(builtInBrushFolder()));
              problems = library->errors();
            } catch (const gpu::GlError& e) {
              problems.push_back(std::string("brushes not compiled: ") + e.what());
            }
            const gpu::BrushCatalog catalog = library ? library->catalog() : scanBrushes();
            std::vector<const gpu::BrushManifest*> usable;
            if (library) {
              usable = library->brushes();
            } else {
              for (const gpu::BrushCatalogError& e : catalog.errors())
                problems.push_back(e.message);
              for (const gpu::BrushManifest& b : catalog.brushes())
                usable.push_back(&b);
            }
            if (*json) {
              nlohmann::json brushes = nlohmann::json::array(), errors = nlohmann::json::array();
              for (const gpu::BrushManifest* brush : usable) {
                const gpu::BrushManifest& b = *brush;
                nlohmann::json parameters = nlohmann::json::array();
                for (const gpu::BrushParameter& p : b.parameters)
                  parameters.push_back({{"id", p.id},
                                        {"label", p.label},
                                        {"type", gpu::toManifestName(p.type)},
                                        {"default", p.defaultValue},
                                        {"min", p.min},
                                        {"max", p.max}});
                nlohmann::json writes = nlohmann::json::array();
                for (core::EditLayer l : b.writes)
                  writes.push_back(gpu::toManifestName(l));
                brushes.push_back({{"id", b.id},
                                   {"name", b.name},
                                   {"category", gpu::toManifestName(b.category)},
                                   {"area", gpu::toManifestName(b.area)},
                                   {"falloff", gpu::toManifestName(b.falloff)},
                                   {"writes", writes},
                                   {"folder", b.folder.string()},
                                   {"parameters", parameters}});
              }
              for (const std::string& message : problems)
                errors.push_back(message);
              std::cout << app::JsonReply{{"brushes", brushes}, {"errors", errors}}.dump() << "\n";
              return kExitOk;
            }
            for (const gpu::BrushManifest* brush : usable) {
              const gpu::BrushManifest& b = *brush;
              std::cout << b.id << "  (" << b.name << ", " << gpu::toManifestName(b.category)
                        << ")  " << b.description << "\n";
              for (const gpu::BrushParameter& p : b.parameters)
                std::cout << "    --param " << p.id << "=…  " << p.label << " ("
                          << gpu::toManifestName(p.type) << ")\n";
            }
            for (const std::string& message : problems)
              std::cout << "not loaded: " << message << "\n";
            return kExitOk;
          }};
}

} // namespace octaclay::app
