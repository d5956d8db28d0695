#pragma once
// What is cut off in a main window: each dock raised in turn, a panel wider than its dock (it would scroll
// sideways) or a table whose columns are wider than its viewport. Empty when nothing is.
#include <QApplication>
#include <QDockWidget>
#include <QHeaderView>
#include <QMainWindow>
#include <QScrollArea>
#include <QStringList>
#include <QTableView>

namespace hs::test {

inline QStringList clippedParts(QMainWindow* window) {
    QStringList clipped;
    for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
        if (!dock->toggleViewAction()->isChecked())
            continue;
        dock->raise();
        QApplication::processEvents();
        auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
        if (scroll && scroll->widget()->minimumSizeHint().width() > scroll->viewport()->width())
            clipped << QStringLiteral("%1: panel %2 px in %3 px")
                           .arg(dock->objectName())
                           .arg(scroll->widget()->minimumSizeHint().width())
                           .arg(scroll->viewport()->width());
        for (QTableView* table : dock->findChildren<QTableView*>()) {
            if (!table->isVisibleTo(dock))
                continue;
            const int columns = table->horizontalHeader()->length();
            if (columns > table->viewport()->width())
                clipped << QStringLiteral("%1: table %2 %3 px of columns in %4 px")
                               .arg(dock->objectName(), table->objectName())
                               .arg(columns)
                               .arg(table->viewport()->width());
        }
    }
    return clipped;
}

} // namespace hs::test
