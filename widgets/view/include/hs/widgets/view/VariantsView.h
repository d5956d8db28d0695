#pragma once
/// N variants of a case side by side: one hysteroscopic view per scene package, in a grid, all driven by one set of
/// controls (insertion, optic, roll), so a clinician compares the same view of each variant. Up to kMaxVariants.

#include "hs/scene/Scene.h"

#include <QString>
#include <QStringList>
#include <QWidget>

#include <memory>
#include <vector>

class QComboBox;
class QGridLayout;
class QLabel;
class QSlider;

namespace hs::widgets {

class HysteroscopicPreview;

class VariantsView : public QWidget {
    Q_OBJECT

public:
    static constexpr int kMaxVariants = 6;

    explicit VariantsView(QWidget* parent = nullptr);

    /// Shows the first kMaxVariants of `scenes`, each titled by its name (the package's folder name).
    void setScenes(const std::vector<std::shared_ptr<const scene::Scene>>& scenes, const QStringList& names);
    int count() const { return static_cast<int>(m_previews.size()); }
    HysteroscopicPreview* preview(int index) const { return m_previews.at(static_cast<std::size_t>(index)); }

    void setInsertion(double mm);

private:
    void apply();

    QGridLayout* m_grid = nullptr;
    std::vector<HysteroscopicPreview*> m_previews;
    std::vector<QLabel*> m_titles;
    QSlider* m_insertionSlider = nullptr;
    QComboBox* m_opticCombo = nullptr;
    QSlider* m_rollSlider = nullptr;
};

} // namespace hs::widgets
