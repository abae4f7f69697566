// Help ▸ Keyboard and Mouse: the sheet is generated from the window's actions and the viewport's
// gesture table each time it opens.

#include "shortcut_sheet.h"

#include "mouse_gestures.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QVariant>

#include <functional>

namespace octaclay::app {
namespace {

QString plainText(const QString& text) {
  QString t = text;
  t.remove(QRegularExpression(QStringLiteral("&(?!&)")));
  if (t.endsWith(QChar(0x2026))) t.chop(1); // "Save As…"
  return t;
}

} // namespace

QString ShortcutEntry::keysText() const {
  QStringList parts;
  for (const QKeySequence& k : keys)
    parts << k.toString(QKeySequence::NativeText);
  return parts.join(QStringLiteral(", "));
}

QList<ShortcutEntry> collectShortcuts(const QWidget& window) {
  QList<ShortcutEntry> entries;
  QList<const QAction*> seen;
  const auto add = [&](QAction* a, const QString& where) {
    if (a->isSeparator() || a->shortcuts().isEmpty() || seen.contains(a)) return;
    seen << a;
    const QVariant sheetText = a->property(kSheetTextProperty);
    entries.push_back({a, where, sheetText.isValid() ? sheetText.toString() : plainText(a->text()),
                       a->shortcuts()});
  };
  // Menus first, in the menu bar's order, so the sheet reads like the menus.
  std::function<void(QMenu*, const QString&)> walk = [&](QMenu* menu, const QString& path) {
    for (QAction* a : menu->actions()) {
      if (QMenu* sub = a->menu())
        walk(sub, path + QStringLiteral(" ▸ ") + plainText(sub->title()));
      else
        add(a, path);
    }
  };
  if (QMenuBar* bar = window.findChild<QMenuBar*>())
    for (QAction* top : bar->actions())
      if (QMenu* menu = top->menu()) walk(menu, plainText(menu->title()));
  for (QAction* a : window.findChildren<QAction*>())
    add(a, QObject::tr("Window"));
  return entries;
}

ShortcutSheet::ShortcutSheet(const QWidget& window, QWidget* parent) : QDialog(parent) {
  setObjectName(QStringLiteral("shortcutSheet"));
  setWindowTitle(tr("Keyboard and Mouse"));
  table_ = new QTableWidget(this);
  table_->setObjectName(QStringLiteral("shortcutTable"));
  table_->setColumnCount(3);
  table_->setHorizontalHeaderLabels({tr("Keys or mouse"), tr("Does"), tr("Where")});
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->verticalHeader()->hide();
  const auto addRow = [this](const QString& keys, const QString& does, const QString& where) {
    const int row = table_->rowCount();
    table_->insertRow(row);
    table_->setItem(row, 0, new QTableWidgetItem(keys));
    table_->setItem(row, 1, new QTableWidgetItem(does));
    table_->setItem(row, 2, new QTableWidgetItem(where));
  };
  for (const ShortcutEntry& e : collectShortcuts(window))
    addRow(e.keysText(), e.text, e.where);
  for (const Gesture& g : viewportGestures())
    addRow(g.input, g.action, tr("Viewport"));
  // The descriptions take the room the keys and places leave, the long ones (F, Shift+F)
  // wrapped in it rather than running off the sheet's edge.
  table_->setWordWrap(true);
  QHeaderView* columns = table_->horizontalHeader();
  columns->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  columns->setSectionResizeMode(1, QHeaderView::Stretch);
  columns->setSectionResizeMode(2, QHeaderView::ResizeToContents);
  table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(table_);
  layout->addWidget(buttons);
  resize(640, 520);
}

} // namespace octaclay::app
