// make_resources <resources-folder>: regenerates the shipped materials and the studio environment
// map (see resources/README.md). The output depends on nothing but this program, so running it
// again writes the same bytes.

#include "matcap_generator.h"
#include "material_generator.h"

#include <exception>
#include <iostream>
#include <string_view>

int main(int argc, char** argv) {
  if (argc != 2 || std::string_view(argv[1]) == "--help" || std::string_view(argv[1]) == "-h") {
    std::cerr
        << "usage: make_resources <resources-folder>\n"
           "Writes <resources-folder>/materials/<id>/ (material.json and four 256x256 PNG "
           "maps)\nfor brick, stone, wood, red-plastic and mirror, and "
           "<resources-folder>/environment/studio.png and <resources-folder>/matcaps/<id>.png.\n";
    return argc == 2 ? 0 : 2;
  }
  try {
    octaclay::tools::writeResources(argv[1]);
    octaclay::tools::writeMatcaps(std::filesystem::path(argv[1]) / "matcaps");
  } catch (const std::exception& e) {
    std::cerr << "make_resources: " << e.what() << '\n';
    return 1;
  }
  std::cout << "make_resources: wrote " << argv[1] << "/materials and " << argv[1]
            << "/environment and " << argv[1] << "/matcaps\n";
  return 0;
}
