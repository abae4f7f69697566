// The Objects menu's doors on the Modeller beside modeller_objects.cpp (issue 33, item 3): a
// duplicate or mirrored duplicate of the edited object, and its world box for Frame Selected.
#include "modeller.h"

#include "octaclay/core/document/document_mirror.h"

namespace octaclay::app {

QString Modeller::duplicateActiveObject(int mirrorAxis) {
  if (!hasDocument()) return tr("There is no object to duplicate");
  if (mirrorAxis < -1 || mirrorAxis > 2) return tr("There is no axis %1").arg(mirrorAxis);
  if (scene_.objects.size() >= core::kMaxSceneObjects)
    return tr("The scene already holds the most objects a document holds (%1)")
        .arg(core::kMaxSceneObjects);
  strokes_.settle();
  if (session_.stroking()) return tr("Finish the stroke first");
  const core::SceneObject& source = objectAt(active_);
  core::SceneObject copy;
  copy.name = source.name; // addObject makes it unique: "Body.001"
  copy.document = mirrorAxis < 0 ? document() : core::mirrorDocument(document(), mirrorAxis);
  copy.transform =
      mirrorAxis < 0 ? source.transform : core::mirroredTransform(source.transform, mirrorAxis);
  copy.visible = true;
  copy.locked = false;
  const std::string from = source.name;
  const QString label = mirrorAxis < 0 ? tr("Duplicate %1").arg(QString::fromStdString(from))
                                       : tr("Mirror %1 across %2")
                                             .arg(QString::fromStdString(from))
                                             .arg(QChar('X' + mirrorAxis));
  if (!addObject(std::move(copy), label))
    return error().isEmpty() ? tr("Could not duplicate the object") : error();
  return {};
}

core::BoundingBox Modeller::activeWorldBounds() const {
  core::BoundingBox box;
  if (!hasDocument()) return box;
  const core::ObjectTransform& transform = objectAt(active_).transform;
  for (const core::Vec4f& p : document().positions.texels())
    box.extend(core::applyTransform(transform, p.xyz()));
  return box;
}

} // namespace octaclay::app
