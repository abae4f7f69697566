#include "add_menu.h"

#include "main_window.h"
#include "modeller.h"
#include "user_messages.h"
#include "viewport_widget.h"

#include "octaclay/core/document/scene.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"

#include <QAction>
#include <QCursor>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

namespace octaclay::app {
namespace {

// Scene units: the new object's bounding-box diagonal against the scene's.
constexpr float kShareOfScene = 0.25f;

// What the Add menu makes: a ball of a base shape, a torus or a sheet.
enum class AddedKind { Ball, Torus, Plane, Disc };

struct AddedShape {
  AddedKind kind = AddedKind::Ball;
  core::BaseShape ball = core::BaseShape::Sphere;
};

std::string shapeName(const AddedShape& shape) {
  switch (shape.kind) {
  case AddedKind::Torus:
    return "torus";
  case AddedKind::Plane:
    return "plane";
  case AddedKind::Disc:
    return "disc";
  case AddedKind::Ball:
    break;
  }
  return std::string(core::baseShapeName(shape.ball));
}

// The shape's image at N = n, as `octaclay-cli new` makes it: a torus's height around its
// tube chosen from its radii (its cells about square: a thin ring sampled evenly).
core::GeometryImage shapeImage(const AddedShape& shape, int n) {
  switch (shape.kind) {
  case AddedKind::Torus: {
    const core::Torus torus;
    return core::makeTorus(torus, n, core::torusHeight(torus, n));
  }
  case AddedKind::Plane:
    return core::makeSheet(core::Sheet::Square, n);
  case AddedKind::Disc:
    return core::makeSheet(core::Sheet::Disc, n);
  case AddedKind::Ball:
    break;
  }
  return core::makeBaseShape(shape.ball, n);
}

// The rotation (ObjectTransform's degrees about X, then Y) that turns the object's own z axis,
// along which the cylinder, capsule and torus are made, to the unit vector up.
core::Vec3f standing(core::Vec3f up) {
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  const double x = -std::asin(std::clamp(double(up.y), -1.0, 1.0)) * kDegrees;
  const double y = std::atan2(double(up.x), double(up.z)) * kDegrees;
  return {static_cast<float>(x), static_cast<float>(y), 0.0f};
}

// As Blender's Add: the new object stands upright in the scene (its z along the scene's up, y)
// at the view's centre; added with Shift+A over a surface it stands on that surface instead,
// centred on the point under the pointer, its z along the normal there (a hat on a head, a
// nose out of a face, a ring around what it rests on).
void addShape(MainWindow& window, const AddedShape& shape, const std::optional<SurfacePick>& on) {
  Modeller& modeller = *window.modeller();
  if (!modeller.hasDocument()) return;
  const int n = modeller.document().size();
  core::SceneObject object;
  std::string name = shapeName(shape);
  if (!name.empty()) name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
  object.name = name;
  object.document = core::makeDocument(shapeImage(shape, n > 1 ? n : 256));
  const float sceneSize = core::sceneBounds(modeller.scene()).diagonal();
  const float ownSize = core::boundingBox(object.document.positions).diagonal();
  const float scale = ownSize > 0 && sceneSize > 0 ? kShareOfScene * sceneSize / ownSize : 1.0f;
  object.transform.scale = {scale, scale, scale};
  if (on) {
    object.transform.translation = on->position;
    object.transform.rotationDegrees = standing(on->normal);
  } else {
    double focal[3];
    window.viewport()->renderer()->GetActiveCamera()->GetFocalPoint(focal);
    object.transform.translation = {float(focal[0]), float(focal[1]), float(focal[2])};
    object.transform.rotationDegrees = standing({0.0f, 1.0f, 0.0f});
  }
  if (!modeller.addObject(std::move(object)))
    showStatusMessage(*window.statusBar(),
                      MainWindow::tr("Could not add the %1: %2")
                          .arg(QString::fromStdString(name), modeller.error()),
                      8000);
}

} // namespace

void addAddMenu(MainWindow& window) {
  QMenu* menu = window.menuBar()->addMenu(MainWindow::tr("&Add"));
  menu->setObjectName("menuAdd");
  // Where Shift+A found a surface for the menu it pops up; the menu bar's Add clears it.
  auto pointed = std::make_shared<std::optional<SurfacePick>>();
  QObject::connect(menu, &QMenu::aboutToShow, menu, [pointed] { pointed->reset(); });
  const std::pair<AddedShape, QString> shapes[] = {
      {{AddedKind::Ball, core::BaseShape::Sphere}, MainWindow::tr("&Sphere")},
      {{AddedKind::Ball, core::BaseShape::Cube}, MainWindow::tr("&Cube")},
      {{AddedKind::Ball, core::BaseShape::Cylinder}, MainWindow::tr("C&ylinder")},
      {{AddedKind::Ball, core::BaseShape::Blob}, MainWindow::tr("&Blob")},
      {{AddedKind::Ball, core::BaseShape::Capsule}, MainWindow::tr("Ca&psule")},
      {{AddedKind::Torus}, MainWindow::tr("&Torus")},
      {{AddedKind::Plane}, MainWindow::tr("P&lane")},
      {{AddedKind::Disc}, MainWindow::tr("D&isc")}};
  for (const auto& [shape, text] : shapes) {
    QAction* a = menu->addAction(text);
    std::string id = shapeName(shape);
    if (!id.empty()) id[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(id[0])));
    a->setObjectName(QString::fromStdString("actionAdd" + id));
    a->setStatusTip(MainWindow::tr("Adds a new object, upright at the view's centre (Shift+A in "
                                   "the view: standing on the surface under the pointer), and "
                                   "edits it"));
    QObject::connect(a, &QAction::triggered, &window, [&window, shape, pointed] {
      const std::optional<SurfacePick> on = *pointed;
      pointed->reset();
      addShape(window, shape, on);
    });
  }
  // Shift+A in the view (Blender's key): the Add menu at the pointer, for the surface under it.
  QAction* atPointer = new QAction(MainWindow::tr("Add at the Pointer"), &window);
  atPointer->setObjectName("actionAddAtPointer");
  atPointer->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_A));
  atPointer->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  window.viewport()->addAction(atPointer);
  QObject::connect(atPointer, &QAction::triggered, &window, [&window, menu, pointed] {
    ViewportWidget* view = window.viewport();
    const QPoint global = QCursor::pos();
    const QPoint local = view->mapFromGlobal(global);
    const std::optional<SurfacePick> on =
        view->rect().contains(local) ? view->surfaceAt(local) : std::nullopt;
    menu->popup(global); // shows it (aboutToShow clears the last pick) without blocking
    *pointed = on;
  });
  menu->addSeparator();
  QAction* remove = menu->addAction(MainWindow::tr("&Delete Object"));
  remove->setObjectName("actionDeleteObject");
  remove->setShortcut(QKeySequence::Delete);
  remove->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  window.viewport()->addAction(remove); // the Delete key where the viewport has the focus
  QObject::connect(remove, &QAction::triggered, &window, [&window] {
    const QString why = window.modeller()->deleteActiveObject();
    if (!why.isEmpty()) showStatusMessage(*window.statusBar(), why, 8000);
  });
}

} // namespace octaclay::app
