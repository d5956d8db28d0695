#include "hs/widgets/panels/SceneTree.h"

#include "hs/widgets/panels/MaterialsPanel.h"
#include "hs/widgets/view/SceneParts.h"

#include <QHeaderView>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <cmath>
#include <map>

namespace hs::widgets {

namespace {

constexpr int kKeyRole = Qt::UserRole;
constexpr int kPathologyRole = Qt::UserRole + 1;
constexpr int kOutOfDateRole = Qt::UserRole + 2;

QString partName(const ScenePart& part) {
    const QString name = QString::fromStdString(part.name);
    switch (part.kind) {
    case PartKind::Organ:
        return SceneTree::tr("Organ (shape model)");
    case PartKind::DisplacedOrgan:
        return part.parent.empty() ? SceneTree::tr("Growth") : SceneTree::tr("Displaced organ");
    case PartKind::GrownPathology:
        return SceneTree::tr("%1 (grown)").arg(name);
    case PartKind::MergedRegion:
        if (part.parent.empty())
            return SceneTree::tr("Merged body");
        return part.pathology < 0 ? SceneTree::tr("Wall") : SceneTree::tr("%1 (merged)").arg(name);
    case PartKind::Tissues:
        return SceneTree::tr("Tetrahedral mesh");
    case PartKind::TissueRegion:
        return part.pathology < 0 && part.tissue ? tissueName(*part.tissue) : name;
    case PartKind::Surface:
        return SceneTree::tr("Visual surface (textured)");
    case PartKind::Simulation:
        return SceneTree::tr("Simulation mesh");
    }
    return name;
}

generate::Stage stageOfPart(const ScenePart& part) {
    return part.kind == PartKind::Simulation ? generate::Stage::Scene : stageOf(part.layer);
}

} // namespace

SceneTree::SceneTree(QWidget* parent) : QWidget(parent), m_tree(new QTreeWidget(this)) {
    setObjectName("sceneTree");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_tree->setObjectName("sceneTreeView");
    m_tree->setColumnCount(kColumnCount);
    m_tree->setHeaderLabels({tr("Part"), tr("Opacity")});
    m_tree->header()->setSectionResizeMode(kNameColumn, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(kOpacityColumn, QHeaderView::ResizeToContents);
    m_tree->header()->setStretchLastSection(false);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_tree->setToolTip(tr("What the 3-D view shows: tick a part to show it, set its opacity to see inside it"));
    layout->addWidget(m_tree);
    connect(m_tree, &QTreeWidget::itemChanged, this, &SceneTree::onItemChanged);
    connect(m_tree, &QTreeWidget::itemSelectionChanged, this, &SceneTree::onSelectionChanged);
}

void SceneTree::setParts(SceneParts* parts) {
    m_parts = parts;
    refresh();
}

void SceneTree::setCurrentCheck(std::function<bool(generate::Stage)> isCurrent) {
    m_isCurrent = std::move(isCurrent);
    refreshMarks();
}

QTreeWidgetItem* SceneTree::itemOf(const std::string& key) const {
    const QString k = QString::fromStdString(key);
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it)
        if ((*it)->data(kNameColumn, kKeyRole).toString() == k)
            return *it;
    return nullptr;
}

void SceneTree::refresh() {
    const int selected = selectedPathology();
    m_updating = true;
    m_tree->clear();
    if (m_parts) {
        std::map<std::string, QTreeWidgetItem*> items;
        for (const ScenePart& part : m_parts->parts()) {
            const auto parent = items.find(part.parent);
            auto* item = parent == items.end() ? new QTreeWidgetItem(m_tree) : new QTreeWidgetItem(parent->second);
            items[part.key] = item;
            item->setText(kNameColumn, partName(part));
            item->setData(kNameColumn, kKeyRole, QString::fromStdString(part.key));
            item->setData(kNameColumn, kPathologyRole, part.pathology);
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
            item->setCheckState(kNameColumn, m_parts->isShown(part.key) ? Qt::Checked : Qt::Unchecked);
            auto* opacity = new QSpinBox(m_tree);
            opacity->setObjectName(QStringLiteral("opacity:%1").arg(QString::fromStdString(part.key)));
            opacity->setRange(0, 100);
            opacity->setSingleStep(10);
            opacity->setSuffix(QStringLiteral(" %"));
            opacity->setValue(static_cast<int>(std::lround(100.0 * m_parts->opacity(part.key))));
            opacity->setToolTip(tr("Opacity of %1: lower it to see the parts inside").arg(partName(part)));
            opacity->setAccessibleName(tr("Opacity of %1").arg(partName(part)));
            const std::string key = part.key;
            connect(opacity, qOverload<int>(&QSpinBox::valueChanged), this, [this, key](int percent) {
                if (!m_parts)
                    return;
                m_parts->setOpacity(key, percent / 100.0);
                // A group's opacity is its parts': their boxes follow.
                for (const ScenePart& p : m_parts->parts())
                    if (p.parent == key)
                        if (QTreeWidgetItem* child = itemOf(p.key))
                            if (auto* box = qobject_cast<QSpinBox*>(m_tree->itemWidget(child, kOpacityColumn))) {
                                const QSignalBlocker block(box);
                                box->setValue(percent);
                            }
                emit displayChanged();
            });
            m_tree->setItemWidget(item, kOpacityColumn, opacity);
        }
        m_tree->expandAll();
    }
    m_updating = false;
    refreshMarks();
    if (selected >= 0)
        selectPathology(selected);
}

void SceneTree::refreshMarks() {
    if (!m_parts)
        return;
    m_updating = true;
    for (const ScenePart& part : m_parts->parts()) {
        QTreeWidgetItem* item = itemOf(part.key);
        if (!item)
            continue;
        const bool outOfDate = m_isCurrent && !m_isCurrent(stageOfPart(part));
        item->setData(kNameColumn, kOutOfDateRole, outOfDate);
        const QString name = partName(part);
        item->setText(kNameColumn, outOfDate && part.parent.empty() ? tr("%1 — out of date").arg(name) : name);
        item->setForeground(kNameColumn, outOfDate ? QBrush(QColor(200, 110, 0)) : QBrush());
        item->setToolTip(kNameColumn, outOfDate ? tr("The case has changed since this stage ran: what it shows is "
                                                     "not the case as it is now, until the stage reruns")
                                                : QString());
    }
    m_updating = false;
}

void SceneTree::onItemChanged(QTreeWidgetItem* item, int column) {
    if (m_updating || !m_parts || column != kNameColumn)
        return;
    const std::string key = item->data(kNameColumn, kKeyRole).toString().toStdString();
    m_parts->setShown(key, item->checkState(kNameColumn) == Qt::Checked);
    refreshChecks(); // a group's box ticks its parts; a part's box re-reads its group's
    emit visibilityChanged();
    emit displayChanged();
}

void SceneTree::refreshChecks() {
    if (!m_parts)
        return;
    const bool updating = m_updating;
    m_updating = true;
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        const std::string k = (*it)->data(kNameColumn, kKeyRole).toString().toStdString();
        (*it)->setCheckState(kNameColumn, m_parts->isShown(k) ? Qt::Checked : Qt::Unchecked);
    }
    m_updating = updating;
}

void SceneTree::onSelectionChanged() {
    if (m_updating)
        return;
    const int index = selectedPathology();
    if (m_parts)
        m_parts->highlightPathology(index);
    emit displayChanged();
    if (index >= 0)
        emit pathologySelected(index);
}

int SceneTree::selectedPathology() const {
    const QList<QTreeWidgetItem*> selected = m_tree->selectedItems();
    return selected.isEmpty() ? -1 : selected.front()->data(kNameColumn, kPathologyRole).toInt();
}

void SceneTree::selectPathology(int index) {
    QTreeWidgetItem* first = nullptr;
    QTreeWidgetItem* shown = nullptr;
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        if ((*it)->data(kNameColumn, kPathologyRole).toInt() != index || index < 0)
            continue;
        if (!first)
            first = *it;
        if (!shown && (*it)->checkState(kNameColumn) == Qt::Checked)
            shown = *it;
    }
    QTreeWidgetItem* item = shown ? shown : first;
    m_updating = true;
    m_tree->clearSelection();
    if (item) {
        item->setSelected(true);
        m_tree->scrollToItem(item);
    }
    m_updating = false;
    if (m_parts)
        m_parts->highlightPathology(item ? index : -1);
    emit displayChanged();
}

} // namespace hs::widgets
