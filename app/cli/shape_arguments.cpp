#include "shape_arguments.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/sheet.h"

namespace octaclay::app {

void checkShapeArguments(const std::string& shape, bool capsuleOptionsGiven) {
  const auto base = core::parseBaseShape(shape);
  if (!base && shape != "torus" && shape != "plane" && shape != "disc")
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "unknown shape '" + shape +
                          "'; use sphere, cube, cylinder, blob, capsule, torus, plane or disc");
  if (base != core::BaseShape::Capsule && capsuleOptionsGiven)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "--radius and --length shape a capsule; --shape " + shape + " takes neither");
}

core::GeometryImage makeShapeImage(const std::string& shape, int n, const core::Capsule& capsule,
                                   const core::Torus& torus, int torusHeight) {
  checkShapeArguments(shape, false);
  if (shape == "torus") {
    if (n < core::kMinTorusSize)
      throw core::Error(core::ErrorKind::InvalidArgument, "a torus needs --size 4 or more");
    return core::makeTorus(torus, n, torusHeight > 0 ? torusHeight : core::torusHeight(torus, n));
  }
  if (shape == "plane" || shape == "disc")
    return core::makeSheet(shape == "disc" ? core::Sheet::Disc : core::Sheet::Square, n);
  const core::BaseShape base = *core::parseBaseShape(shape);
  return base == core::BaseShape::Capsule ? core::makeCapsule(n, capsule)
                                          : core::makeBaseShape(base, n);
}

} // namespace octaclay::app
