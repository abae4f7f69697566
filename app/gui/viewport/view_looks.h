#pragma once

#include <QColor>
#include <QString>
#include <QStringList>

namespace octaclay::app {

/// How the viewport looks, whatever the model: the material (the lit, painted look or a matcap),
/// the wireframe overlay and the background. Kept in QSettings under "view/".
struct ViewLooks {
  QString material = QStringLiteral("lit"); ///< "lit" or one of matcapIds()
  bool wireframe = false;                   ///< the displayed level's edges over the model
  bool gradient = false;                    ///< background: top to bottom, else top alone
  QColor backgroundTop = QColor::fromRgbF(0.27f, 0.29f, 0.33f);
  QColor backgroundBottom = QColor::fromRgbF(0.1f, 0.11f, 0.13f);

  bool operator==(const ViewLooks&) const = default;

  /// The looks QSettings holds (the defaults where it holds none or an unknown material).
  static ViewLooks fromSettings();
  void save() const;
};

/// The shipped matcaps in menu order (resources/matcaps/<id>.png): clay, red-wax, chrome, skin.
QStringList matcapIds();
/// A matcap's name for menus ("Red wax").
QString matcapTitle(const QString& id);
/// Where matcap id's image is.
QString matcapPath(const QString& id);

} // namespace octaclay::app
