#include "looks_menu.h"

#include "color_button.h"
#include "viewport_widget.h"

#include <QActionGroup>
#include <QCheckBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QMenu>

namespace octaclay::app {
namespace {

void changeLooks(ViewportWidget* viewport, const std::function<void(ViewLooks&)>& change) {
  ViewLooks looks = viewport->looks();
  change(looks);
  viewport->setLooks(looks);
  looks.save();
}

// View ▸ Background…: a colour, or a gradient from the top colour to the bottom one, shown on
// the viewport as it is edited; Cancel puts the previous one back.
void editBackground(ViewportWidget* viewport) {
  const ViewLooks before = viewport->looks();
  QDialog dialog(viewport->window());
  dialog.setObjectName("backgroundDialog");
  dialog.setWindowTitle(QDialog::tr("Background"));
  auto* form = new QFormLayout(&dialog);
  auto* gradient = new QCheckBox(QDialog::tr("Gradient from top to bottom"), &dialog);
  gradient->setObjectName("gradient");
  gradient->setChecked(before.gradient);
  auto* top = new ColorButton(&dialog);
  top->setObjectName("top");
  top->setColor(before.backgroundTop);
  auto* bottom = new ColorButton(&dialog);
  bottom->setObjectName("bottom");
  bottom->setColor(before.backgroundBottom);
  bottom->setEnabled(before.gradient);
  form->addRow(gradient);
  form->addRow(QDialog::tr("Colour (top)"), top);
  form->addRow(QDialog::tr("Bottom"), bottom);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel |
                                       QDialogButtonBox::RestoreDefaults);
  form->addRow(buttons);
  const auto preview = [=] {
    bottom->setEnabled(gradient->isChecked());
    ViewLooks looks = viewport->looks();
    looks.gradient = gradient->isChecked();
    looks.backgroundTop = top->color();
    looks.backgroundBottom = bottom->color();
    viewport->setLooks(looks);
  };
  QObject::connect(gradient, &QCheckBox::toggled, &dialog, preview);
  QObject::connect(top, &ColorButton::colorChanged, &dialog, preview);
  QObject::connect(bottom, &ColorButton::colorChanged, &dialog, preview);
  QObject::connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked,
                   &dialog, [=] {
                     const ViewLooks defaults;
                     gradient->setChecked(defaults.gradient);
                     top->setColor(defaults.backgroundTop);
                     bottom->setColor(defaults.backgroundBottom);
                   });
  QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  if (dialog.exec() == QDialog::Accepted)
    viewport->looks().save();
  else
    viewport->setLooks(before);
}

} // namespace

void addLookActions(QMenu* view, ViewportWidget* viewport) {
  viewport->setLooks(ViewLooks::fromSettings());
  view->addSeparator();
  QMenu* material = view->addMenu(QMenu::tr("&Material"));
  material->setObjectName("menuMaterial");
  auto* group = new QActionGroup(material);
  QStringList ids{QStringLiteral("lit")};
  ids << matcapIds();
  for (const QString& id : ids) {
    const QString title = id == "lit" ? QMenu::tr("Lit (painted colours, shine)") : matcapTitle(id);
    QAction* a = material->addAction(title);
    QString name = id;
    name.remove('-');
    name[0] = name[0].toUpper();
    a->setObjectName("actionMaterial" + name);
    a->setCheckable(true);
    a->setChecked(viewport->looks().material == id);
    a->setToolTip(id == "lit" ? QMenu::tr("The model lit by a headlight, with its paint, "
                                          "shine and reflections")
                              : QMenu::tr("A matcap: the look of %1 whatever the light; painted "
                                          "colours tint it")
                                    .arg(title.toLower()));
    group->addAction(a);
    QObject::connect(a, &QAction::triggered, viewport,
                     [=] { changeLooks(viewport, [&](ViewLooks& l) { l.material = id; }); });
  }
  QAction* wireframe = view->addAction(QMenu::tr("&Wireframe"));
  wireframe->setObjectName("actionWireframe");
  wireframe->setCheckable(true);
  wireframe->setChecked(viewport->looks().wireframe);
  wireframe->setToolTip(QMenu::tr("Draw the edges of the displayed triangles over the model"));
  QObject::connect(wireframe, &QAction::toggled, viewport, [=](bool on) {
    changeLooks(viewport, [&](ViewLooks& l) { l.wireframe = on; });
  });
  QAction* background = view->addAction(QMenu::tr("&Background…"));
  background->setObjectName("actionBackground");
  QObject::connect(background, &QAction::triggered, viewport, [=] { editBackground(viewport); });
}

} // namespace octaclay::app
