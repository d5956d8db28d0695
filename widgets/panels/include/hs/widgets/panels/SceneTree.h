#pragma once
/// The scene tree (as 3D Slicer's Data module, MITK's Data Manager, ParaView's Pipeline Browser): every part of the
/// case's results the 3-D view can show (SceneParts), each with a check box for its visibility and an opacity, so a
/// growth is watched inside a translucent organ. Selecting a pathology's part selects the pathology (the list and a
/// pick in 3-D select it here too); a stage an edit has outdated is marked until it reruns.

#include "hs/generate/Seeds.h"

#include <QWidget>

#include <functional>
#include <string>

class QTreeWidget;
class QTreeWidgetItem;

namespace hs::widgets {

class SceneParts;

class SceneTree : public QWidget {
    Q_OBJECT

public:
    enum Column { kNameColumn, kOpacityColumn, kColumnCount };

    explicit SceneTree(QWidget* parent = nullptr);

    /// The parts the tree lists; nullptr lists none.
    void setParts(SceneParts* parts);
    /// Whether a stage's results match the case as it is now (the session's isCurrent); parts of a stage that does
    /// not are marked "out of date".
    void setCurrentCheck(std::function<bool(generate::Stage)> isCurrent);
    /// Lists the parts anew (after a result, a mesh opened, a package reviewed) and re-marks what is out of date.
    void refresh();
    /// Re-marks what is out of date (after an edit).
    void refreshMarks();
    /// Re-reads each part's visibility (after the Mesh panel hid a tissue region).
    void refreshChecks();

    /// Selects the first shown part of pathology `index` (else its first part); -1 clears the selection.
    void selectPathology(int index);
    int selectedPathology() const;

    QTreeWidget* tree() const { return m_tree; }
    /// The item of the part `key`; nullptr when it is not listed.
    QTreeWidgetItem* itemOf(const std::string& key) const;

signals:
    /// The user (or a pick) selected a part of pathology `index`.
    void pathologySelected(int index);
    /// A part was shown, hidden or made translucent, or the selection's outline moved: the view needs drawing.
    void displayChanged();
    /// The user showed or hid a part (the Mesh panel's region boxes follow).
    void visibilityChanged();

private:
    void onItemChanged(QTreeWidgetItem* item, int column);
    void onSelectionChanged();

    QTreeWidget* m_tree;
    SceneParts* m_parts = nullptr;
    std::function<bool(generate::Stage)> m_isCurrent;
    bool m_updating = false;
};

} // namespace hs::widgets
