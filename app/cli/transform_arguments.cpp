#include "transform_arguments.h"

#include "octaclay/core/error.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace octaclay::app {

namespace {

[[noreturn]] void badArgument(const std::string& message) {
  throw core::Error(core::ErrorKind::InvalidArgument, message);
}

std::vector<float> numbers(const std::string& text, const std::string& option) {
  std::vector<float> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size())
      badArgument(option + ": '" + item + "' is not a number");
    if (!std::isfinite(v) || std::abs(v) > 3.4e38)
      badArgument(option + ": '" + item + "' is not a finite number a float holds");
    values.push_back(static_cast<float>(v));
  }
  if (!text.empty() && text.back() == ',') badArgument(option + ": '" + text + "' ends in a comma");
  return values;
}

core::Vec3f three(const std::string& text, const std::string& option, const char* meaning) {
  const std::vector<float> v = numbers(text, option);
  if (v.size() != 3) badArgument(option + " takes " + meaning + " as x,y,z, not '" + text + "'");
  return {v[0], v[1], v[2]};
}

} // namespace

void addTransformOptions(CLI::App& sub, TransformArguments& arguments) {
  sub.add_option("--translate", arguments.translate,
                 "x,y,z: where the object's origin sits in the scene");
  sub.add_option("--rotate", arguments.rotate,
                 "x,y,z: degrees about the scene's X, then Y, then Z axis");
  sub.add_option("--scale", arguments.scale,
                 "s or sx,sy,sz: the object's size along its own axes (1 keeps it)");
}

core::ObjectTransform appliedTransform(core::ObjectTransform transform,
                                       const TransformArguments& arguments) {
  if (!arguments.translate.empty())
    transform.translation = three(arguments.translate, "--translate", "a position");
  if (!arguments.rotate.empty())
    transform.rotationDegrees = three(arguments.rotate, "--rotate", "angles in degrees");
  if (!arguments.scale.empty()) {
    const std::vector<float> v = numbers(arguments.scale, "--scale");
    if (v.size() == 1)
      transform.scale = {v[0], v[0], v[0]};
    else if (v.size() == 3)
      transform.scale = {v[0], v[1], v[2]};
    else
      badArgument("--scale takes one factor or three (sx,sy,sz), not '" + arguments.scale + "'");
  }
  if (const auto problem = core::transformProblem(transform)) badArgument(*problem);
  return transform;
}

int parseAxis(const std::string& text, const std::string& option) {
  if (text == "x" || text == "X") return 0;
  if (text == "y" || text == "Y") return 1;
  if (text == "z" || text == "Z") return 2;
  badArgument(option + " takes x, y or z, not '" + text + "'");
}

} // namespace octaclay::app
