#include "object_merge.h"

#include "modeller.h"
#include "viewport_widget.h"

#include "octaclay/core/merge/merge.h"

#include <QMessageBox>
#include <QStatusBar>

#include <algorithm>
#include <tuple>

namespace octaclay::app {
namespace {

// The object's transform as the merge's affine placement: world = L · p + t, the matrix
// core::worldPositions applies (as `octaclay-cli merge` places its parts).
core::PartTransform placement(const core::ObjectTransform& t) {
  const auto l = core::linearPart(t);
  core::PartTransform result;
  result.m = {l[0], l[1], l[2], t.translation.x, l[3], l[4], l[5], t.translation.y,
              l[6], l[7], l[8], t.translation.z, 0,    0,    0,    1};
  return result;
}

} // namespace

ObjectMerge::ObjectMerge(Parts parts, QObject* parent)
    : QObject(parent), parts_(parts), runner_(parts.window) {
  setObjectName(QStringLiteral("objectMerge"));
}

std::vector<int> ObjectMerge::chosenObjects(const std::vector<int>& selected) const {
  if (selected.size() >= 2) return selected;
  // Every shown object but the planes and discs (a sheet encloses nothing: a ground plate under
  // the figure stays as it is).
  std::vector<int> visible;
  const Modeller& modeller = *parts_.modeller;
  for (int k = 0; k < modeller.objectCount(); ++k) {
    const core::SceneObject& object = modeller.objectAt(k);
    // The edited object's image is the session's (its scene copy may lag behind).
    const core::Document& document =
        k == modeller.activeObject() ? modeller.document() : object.document;
    if (object.visible && document.positions.topology() != core::Topology::Plane)
      visible.push_back(k);
  }
  return visible;
}

void ObjectMerge::refuse(const QString& why, bool box) {
  lastRefusal_ = why;
  parts_.statusBar->showMessage(why, 15000);
  if (!box) return;
  auto* message =
      new QMessageBox(QMessageBox::Warning, tr("Merge"), why, QMessageBox::Ok, parts_.window);
  message->setObjectName(QStringLiteral("mergeRefusal"));
  message->setAttribute(Qt::WA_DeleteOnClose);
  message->open(); // window-modal, does not block the caller
}

bool ObjectMerge::merge(const std::vector<int>& chosen, std::shared_ptr<TaskControl> control) {
  Modeller& modeller = *parts_.modeller;
  lastRefusal_.clear();
  if (!modeller.hasDocument() || !parts_.viewport->glReady()) return false;
  if (parts_.viewport->stroking()) {
    refuse(tr("Finish the stroke first"), false);
    return false;
  }
  if (runner_.busy()) return false;
  std::vector<int> objects = chosen;
  std::sort(objects.begin(), objects.end());
  objects.erase(std::unique(objects.begin(), objects.end()), objects.end());
  if (objects.size() < 2 || objects.front() < 0 || objects.back() >= modeller.objectCount()) {
    refuse(tr("Merge needs two or more objects: select them in the Objects list (Ctrl+click)"));
    return false;
  }
  // Copies taken here, on the GUI thread (the edited object's as edited so far); the worker
  // never touches the modeller.
  auto documents = std::make_shared<std::vector<core::Document>>();
  std::vector<core::PartTransform> placements;
  std::vector<std::string> names;
  int n = 0;
  for (const int k : objects) {
    const core::SceneObject& object = modeller.objectAt(k);
    if (object.locked) {
      refuse(tr("Cannot merge %1: it is locked (untick its lock in the Objects list)")
                 .arg(QString::fromStdString(object.name)));
      return false;
    }
    documents->push_back(k == modeller.activeObject() ? modeller.document() : object.document);
    placements.push_back(placement(object.transform));
    names.push_back(object.name);
    n = std::max(n, documents->back().size());
  }
  const std::string name = modeller.objectAt(objects.front()).name;
  if (!control) control = std::make_shared<TaskControl>();
  auto result = std::make_shared<core::MergeResult>();
  // What tells that the scene changed while the merge ran (input reaching the viewport in the
  // moment before the progress dialog appears): replacing the objects would lose that change.
  const auto mark = [this] {
    Modeller& m = *parts_.modeller;
    return std::tuple(parts_.viewport->stroking(), parts_.viewport->stats().dabs, m.objectCount(),
                      m.activeObject(), m.history().position());
  };
  const auto before = mark();
  const QString error = runner_.run(
      tr("Merging %1 objects at N = %2…").arg(objects.size()).arg(n),
      [documents, placements, names, n, result, control] {
        std::vector<core::MergePart> parts;
        for (std::size_t k = 0; k < documents->size(); ++k)
          parts.push_back({&(*documents)[k], placements[k], names[k]});
        core::MergeOptions options;
        options.size = n;
        *result = core::mergeParts(parts, options, [&control](float done) {
          control->fraction = done;
          return !control->cancel.load();
        });
      },
      control);
  if (control->cancel) {
    refuse(tr("Merge cancelled; the objects are unchanged"), false);
    return false;
  }
  if (!error.isEmpty()) {
    refuse(tr("Cannot merge: %1").arg(error));
    return false;
  }
  if (mark() != before) {
    refuse(tr("The scene changed while merging; nothing was merged"), false);
    return false;
  }
  core::SceneObject merged;
  merged.name = name;
  merged.document = std::move(result->document);
  const QString label = tr("Merge %1 Objects").arg(objects.size());
  if (const QString why = modeller.replaceObjects(objects, std::move(merged), label);
      !why.isEmpty()) {
    refuse(tr("Cannot merge: %1").arg(why));
    return false;
  }
  parts_.statusBar->showMessage(
      tr("Merged %1 objects into %2 (N = %3)")
          .arg(objects.size())
          .arg(QString::fromStdString(modeller.objectAt(modeller.activeObject()).name))
          .arg(n),
      10000);
  return true;
}

} // namespace octaclay::app
