#include "brush_list.h"

#include "brush_panel.h"

#include <QFrame>
#include <QLabel>
#include <QSignalBlocker>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <array>

namespace octaclay::app {
namespace {

constexpr std::array kCategories{gpu::Category::Sculpt, gpu::Category::Paint, gpu::Category::Splat};

QString categoryTitle(gpu::Category category) {
  switch (category) {
  case gpu::Category::Sculpt:
    return BrushPanel::tr("Sculpt");
  case gpu::Category::Paint:
    return BrushPanel::tr("Paint");
  case gpu::Category::Splat:
    return BrushPanel::tr("Splat");
  }
  return {};
}

// Error text with zero-width spaces after path separators, so a long path wraps in the label
// instead of widening the dock.
QString wrappable(const QString& text) {
  QString out;
  out.reserve(text.size() + text.size() / 8);
  for (const QChar c : text) {
    out += c;
    if (c == u'/' || c == u'\\') out += QChar(0x200B);
  }
  return out;
}

} // namespace

void fillBrushTree(QTreeWidget& tree, const std::vector<gpu::BrushManifest>& brushes) {
  const QSignalBlocker block(&tree);
  tree.clear();
  for (const gpu::Category category : kCategories) {
    QTreeWidgetItem* header = nullptr;
    for (const gpu::BrushManifest& brush : brushes) {
      if (brush.category != category) continue;
      if (!header) {
        header = new QTreeWidgetItem(&tree, {categoryTitle(category)});
        header->setFlags(Qt::ItemIsEnabled);
        QFont font = header->font(0);
        font.setBold(true);
        header->setFont(0, font);
      }
      auto* item = new QTreeWidgetItem(header, {QString::fromStdString(brush.name)});
      item->setData(0, kBrushIdRole, QString::fromStdString(brush.id));
      item->setToolTip(0,
                       QStringLiteral("%1\n%2").arg(QString::fromStdString(brush.description),
                                                    QString::fromStdString(brush.folder.string())));
    }
  }
  tree.expandAll();
}

void showBrushErrors(QFrame& frame, QVBoxLayout& layout, const std::vector<std::string>& errors) {
  while (QLayoutItem* item = layout.takeAt(0)) {
    delete item->widget();
    delete item;
  }
  frame.setVisible(!errors.empty());
  if (errors.empty()) return;
  // No translator is installed, so spell the plural out rather than rely on tr()'s %n forms.
  auto* heading = new QLabel(
      errors.size() == 1 ? BrushPanel::tr("1 brush could not be loaded:")
                         : BrushPanel::tr("%1 brushes could not be loaded:").arg(errors.size()));
  QFont bold = heading->font();
  bold.setBold(true);
  heading->setFont(bold);
  layout.addWidget(heading);
  for (const std::string& error : errors) {
    const QString text = QString::fromStdString(error);
    auto* label = new QLabel(wrappable(text));
    label->setObjectName(QStringLiteral("brushError"));
    label->setProperty("error", text);
    label->setTextFormat(Qt::PlainText);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout.addWidget(label);
  }
}

} // namespace octaclay::app
