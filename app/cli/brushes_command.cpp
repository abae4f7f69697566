#include "brush_setup.h"
#include "commands.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace octaclay::app {

Command addBrushesCommand(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  CLI::App* sub = app.add_subcommand("brushes", "List every brush found on the plugin path, "
                                                "with its parameters and any load errors");
  sub->add_flag("--json", *json, "Print one JSON object");
  return {sub, [json]() {
            const gpu::BrushCatalog catalog = scanBrushes();
            if (*json) {
              nlohmann::json brushes = nlohmann::json::array(), errors = nlohmann::json::array();
              for (const gpu::BrushManifest& b : catalog.brushes()) {
                nlohmann::json parameters = nlohmann::json::array();
                for (const gpu::BrushParameter& p : b.parameters)
                  parameters.push_back({{"id", p.id},
                                        {"label", p.label},
                                        {"type", gpu::toManifestName(p.type)},
                                        {"default", p.defaultValue},
                                        {"min", p.min},
                                        {"max", p.max}});
                nlohmann::json writes = nlohmann::json::array();
                for (gpu::BrushLayer l : b.writes)
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
              for (const gpu::BrushCatalogError& e : catalog.errors())
                errors.push_back({{"path", e.path.string()}, {"message", e.message}});
              std::cout << nlohmann::json{{"brushes", brushes}, {"errors", errors}}.dump() << "\n";
              return kExitOk;
            }
            for (const gpu::BrushManifest& b : catalog.brushes()) {
              std::cout << b.id << "  (" << b.name << ", " << gpu::toManifestName(b.category)
                        << ")  " << b.description << "\n";
              for (const gpu::BrushParameter& p : b.parameters)
                std::cout << "    --param " << p.id << "=…  " << p.label << " ("
                          << gpu::toManifestName(p.type) << ")\n";
            }
            for (const gpu::BrushCatalogError& e : catalog.errors())
              std::cout << "not loaded: " << e.message << "\n";
            return kExitOk;
          }};
}

} // namespace octaclay::app
