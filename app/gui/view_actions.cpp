#include "view_actions.h"

#include "viewport_widget.h"

#include <QActionGroup>
#include <QMenu>
#include <QSettings>

namespace octaclay::app {

void addViewActions(QMenu* view, ViewportWidget* viewport) {
  struct Standard {
    const char* text;
    const char* name;
    ViewDirection direction;
    QKeyCombination key;
  };
  const Qt::KeyboardModifiers pad = Qt::KeypadModifier;
  const Qt::KeyboardModifiers ctrlPad = Qt::KeypadModifier | Qt::ControlModifier;
  const Standard standards[] = {
      {QT_TR_NOOP("&Front"), "actionViewFront", ViewDirection::Front, pad | Qt::Key_1},
      {QT_TR_NOOP("&Back"), "actionViewBack", ViewDirection::Back, ctrlPad | Qt::Key_1},
      {QT_TR_NOOP("&Right"), "actionViewRight", ViewDirection::Right, pad | Qt::Key_3},
      {QT_TR_NOOP("&Left"), "actionViewLeft", ViewDirection::Left, ctrlPad | Qt::Key_3},
      {QT_TR_NOOP("&Top"), "actionViewTop", ViewDirection::Top, pad | Qt::Key_7},
      {QT_TR_NOOP("Bott&om"), "actionViewBottom", ViewDirection::Bottom, ctrlPad | Qt::Key_7},
  };
  QMenu* views = view->addMenu(QMenu::tr("&Views"));
  for (const Standard& s : standards) {
    QAction* a = views->addAction(QMenu::tr(s.text));
    a->setObjectName(QString::fromLatin1(s.name));
    a->setShortcut(QKeySequence(s.key));
    QObject::connect(a, &QAction::triggered, viewport,
                     [viewport, d = s.direction] { viewport->setView(d); });
  }

  QAction* ortho = view->addAction(QMenu::tr("&Orthographic"));
  ortho->setObjectName("actionOrthographic");
  ortho->setCheckable(true);
  ortho->setShortcut(QKeySequence(Qt::KeypadModifier | Qt::Key_5));
  ortho->setToolTip(QMenu::tr("Parallel projection (no perspective), for checking proportions"));
  QObject::connect(ortho, &QAction::toggled, viewport, &ViewportWidget::setOrthographic);

  QMenu* orbit = view->addMenu(QMenu::tr("Or&bit"));
  auto* group = new QActionGroup(orbit);
  const auto addOrbit = [&](const QString& text, const char* name, OrbitMode mode,
                            const QString& tip) {
    QAction* a = orbit->addAction(text);
    a->setObjectName(QString::fromLatin1(name));
    a->setCheckable(true);
    a->setToolTip(tip);
    a->setStatusTip(tip);
    group->addAction(a);
    QObject::connect(a, &QAction::triggered, viewport, [viewport, mode] {
      viewport->setOrbitMode(mode);
      QSettings().setValue("view/orbit", mode == OrbitMode::Trackball ? "trackball" : "turntable");
    });
    return a;
  };
  QAction* turntable =
      addOrbit(QMenu::tr("&Turntable"), "actionOrbitTurntable", OrbitMode::Turntable,
               QMenu::tr("Dragging turns the model about its up axis; up stays up"));
  QAction* trackball =
      addOrbit(QMenu::tr("Free T&rackball"), "actionOrbitTrackball", OrbitMode::Trackball,
               QMenu::tr("Dragging turns the model freely, rolling it too"));
  orbit->setToolTipsVisible(true);
  const bool free = QSettings().value("view/orbit").toString() == "trackball";
  (free ? trackball : turntable)->setChecked(true);
  viewport->setOrbitMode(free ? OrbitMode::Trackball : OrbitMode::Turntable);
}

} // namespace octaclay::app
