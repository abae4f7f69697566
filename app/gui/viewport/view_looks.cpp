#include "view_looks.h"

#include "data_folders.h"

#include <QCoreApplication>
#include <QSettings>

#include <filesystem>

namespace octaclay::app {

QStringList matcapIds() {
  return {QStringLiteral("clay"), QStringLiteral("red-wax"), QStringLiteral("chrome"),
          QStringLiteral("skin")};
}

QString matcapTitle(const QString& id) {
  if (id == "clay") return QCoreApplication::translate("ViewLooks", "Clay");
  if (id == "red-wax") return QCoreApplication::translate("ViewLooks", "Red wax");
  if (id == "chrome") return QCoreApplication::translate("ViewLooks", "Chrome");
  if (id == "skin") return QCoreApplication::translate("ViewLooks", "Skin");
  return id;
}

QString matcapPath(const QString& id) {
  const std::filesystem::path file = resourceFolder() / "matcaps" / (id.toStdString() + ".png");
  return QString::fromStdString(file.string());
}

ViewLooks ViewLooks::fromSettings() {
  const QSettings settings;
  ViewLooks looks;
  const QString material = settings.value("view/material", looks.material).toString();
  if (material == "lit" || matcapIds().contains(material)) looks.material = material;
  looks.wireframe = settings.value("view/wireframe", looks.wireframe).toBool();
  looks.gradient = settings.value("view/backgroundGradient", looks.gradient).toBool();
  const auto colour = [&](const char* key, QColor fallback) {
    const QColor c(settings.value(key, fallback.name()).toString());
    return c.isValid() ? c : fallback;
  };
  looks.backgroundTop = colour("view/backgroundTop", looks.backgroundTop);
  looks.backgroundBottom = colour("view/backgroundBottom", looks.backgroundBottom);
  return looks;
}

void ViewLooks::save() const {
  QSettings settings;
  settings.setValue("view/material", material);
  settings.setValue("view/wireframe", wireframe);
  settings.setValue("view/backgroundGradient", gradient);
  settings.setValue("view/backgroundTop", backgroundTop.name());
  settings.setValue("view/backgroundBottom", backgroundBottom.name());
}

} // namespace octaclay::app
