#include "commands.h"
#include "json_output.h"
#include "object_choice.h"

#include "octaclay/core/document/document_info.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/measure/stretch.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace octaclay::app {

Command addInfoCommand(CLI::App& app) {
  struct Options {
    std::string input, object;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "info", "Describe a document: size, topology, bounding box, layers, stretch");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  addObjectOption(*sub, opt->object);
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt]() {
            // info needs the header's layer list, not the layers' pixels.
            ChosenObject chosen = readChosenObject(opt->input, opt->object, {.layers = false});
            const core::DocumentHeader header =
                core::readSceneHeaders(opt->input)[chosen.index].document;
            core::Document document = std::move(chosen.object().document);
            document.hasMask = false;
            core::DocumentInfo info = core::describeDocument(document);
            info.layers = {"positions"};
            for (const char* layer : {"diffuse", "feature", "mask"})
              for (const auto& channel : header.channels)
                if (channel.rfind(std::string(layer) + ".", 0) == 0) {
                  info.layers.emplace_back(layer);
                  break;
                }

            // A torus's or plane's stretch: its own grid's edges along i and j.
            const core::GeometryImage& image = document.positions;
            const bool octahedral = image.topology() == core::Topology::Octahedral;
            const core::StretchSummary stretch = core::summarizeStretch(image);
            const std::string topology(core::topologyName(image.topology()));

            if (opt->json) {
              std::cout << app::JsonReply{{"document", opt->input},
                                          {"format_version", header.formatVersion},
                                          {"size", info.size},
                                          {"topology", topology},
                                          {"width", image.width()},
                                          {"height", image.height()},
                                          {"samples", std::uint64_t(image.texelCount())},
                                          {"vertices", info.vertices},
                                          {"edges", info.edges},
                                          {"triangles", info.triangles},
                                          {"euler", info.euler},
                                          {"closed", info.closed},
                                          {"manifold", info.manifold},
                                          {"seam_gap", info.seamGap},
                                          {"degenerate_triangles", info.degenerateTriangles},
                                          {"bbox", toJson(info.bbox)},
                                          {"layers", info.layers},
                                          {"stretch", toJson(stretch)}}
                               .dump()
                        << "\n";
              return kExitOk;
            }
            const auto& b = info.bbox;
            std::cout << opt->input << "\n";
            if (octahedral)
              std::cout << "  size       N = " << info.size << " (" << info.size + 1 << "x"
                        << info.size + 1 << " samples)\n";
            else
              std::cout << "  size       " << image.width() << "x" << image.height() << " cells ("
                        << image.side() << "x" << image.rows() << " samples)\n";
            if (!octahedral) std::cout << "  topology   " << topology << "\n";
            std::cout << "  mesh       " << info.vertices << " vertices, " << info.edges
                      << " edges, " << info.triangles << " triangles, Euler characteristic "
                      << info.euler << "\n"
                      << "  closed     " << (info.closed ? "yes" : "no") << " (largest seam gap "
                      << info.seamGap << ")\n"
                      << "  manifold   " << (info.manifold ? "yes" : "no") << " ("
                      << info.degenerateTriangles << " degenerate triangles)\n"
                      << "  bbox       [" << b.min.x << ", " << b.min.y << ", " << b.min.z
                      << "] .. [" << b.max.x << ", " << b.max.y << ", " << b.max.z << "], diagonal "
                      << b.diagonal() << "\n"
                      << "  layers    ";
            for (const auto& l : info.layers)
              std::cout << " " << l;
            char line[160];
            std::snprintf(line, sizeof line,
                          octahedral ? "  stretch    longest edge %.1f× median, 99th percentile "
                                       "%.1f×, %.1f %% of samples over 4× median spacing\n"
                                     : "  stretch    longest edge %.1f× median, 99th percentile "
                                       "%.1f×, %.1f %% of grid edges over 4× the median\n",
                          stretch.longestOverMedian, stretch.p99OverMedian,
                          100.0 * stretch.shareOver4x);
            std::cout << "\n" << line;
            return kExitOk;
          }};
}

} // namespace octaclay::app
