#include "about_dialog.h"

#include <QMessageBox>
#include <QtGlobal>
#include <vtkVersion.h>

namespace octaclay::app {

QString aboutText() {
  struct Library {
    const char* name;
    QString version; // empty where the app does not see it (core keeps its libraries inside)
    const char* licence;
  };
  const Library libraries[] = {
      {"Qt", QString::fromLatin1(qVersion()), "LGPL-3.0"},
      {"VTK", QString::fromLatin1(vtkVersion::GetVTKVersion()), "BSD-3-Clause"},
      {"OpenEXR", {}, "BSD-3-Clause"},
      {"OpenCV", {}, "Apache-2.0"},
      {"libpng", {}, "libpng-2.0"},
      {"OpenMesh", {}, "BSD-3-Clause"},
      {"Eigen", {}, "MPL-2.0"},
      {"tinygltf", {}, "MIT"},
      {"CLI11", {}, "BSD-3-Clause"},
      {"nlohmann-json", {}, "MIT"},
      {"libepoxy", {}, "MIT"},
  };
  QString rows;
  for (const Library& l : libraries)
    rows += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td></tr>")
                .arg(QString::fromLatin1(l.name), l.version, QString::fromLatin1(l.licence));
  return QObject::tr("<h3>Octaclay %1</h3>"
                     "<p>Sculpt and paint closed surfaces stored as octahedral geometry "
                     "images.</p>"
                     "<p>Built on these libraries, each under its own licence:</p>"
                     "<table cellspacing=\"4\"><tr><th align=\"left\">Library</th>"
                     "<th align=\"left\">Version</th><th align=\"left\">Licence</th></tr>%2"
                     "</table>")
      .arg(QStringLiteral(OCTACLAY_VERSION), rows);
}

void showAbout(QWidget* parent) {
  auto* box = new QMessageBox(QMessageBox::NoIcon, QObject::tr("About Octaclay"), aboutText(),
                              QMessageBox::Ok, parent);
  box->setObjectName(QStringLiteral("aboutBox"));
  box->setTextFormat(Qt::RichText);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open();
}

} // namespace octaclay::app
