#include "hs/widgets/jobs/JobStatusWidget.h"

#include "hs/widgets/jobs/JobRunner.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QToolButton>
#include <QtGlobal>

#include <algorithm>
#include <utility>

namespace hs::widgets {

namespace {

/// The pipeline's progress steps (Progress::report keys), as the user reads them.
constexpr std::pair<const char*, const char*> kStepNames[] = {
    {"organ", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "organ from the shape model")},
    {"pathology", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "pathologies")},
    {"pathology.grow", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "growing the pathologies")},
    {"pathology.measure", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "measuring the pathologies")},
    {"merge", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "merging")},
    {"merge.union", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "joining the organ and the pathologies")},
    {"merge.labels", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "labelling the contacts")},
    {"merge.cover", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "covering the pathologies")},
    {"merge.validate", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "checking the merged body")},
    {"meshing", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "meshing the body")},
    {"meshing.voxelize", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "voxelizing the body")},
    {"meshing.seed", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "seeding the particles")},
    {"meshing.relax", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "relaxing the particles")},
    {"meshing.tetrahedralize", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "tetrahedralizing")},
    {"meshing.clean", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "removing slivers")},
    {"meshing.interfaceVolume", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "checking the region volumes")},
    {"meshing.quality", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "measuring the mesh quality")},
    {"meshing.done", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "mesh done")},
    {"tissue", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "tissue layers")},
    {"texture", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "texturing")},
    {"texture.synthesis", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "synthesizing the texture")},
    {"texture.vessels", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "growing the vessels")},
    {"texture.atlas", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "unfolding the surface")},
    {"texture.bake", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "baking the maps")},
    {"texture.closeUp", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "refining the surface for close-ups")},
    {"texture.bind", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "binding the surface to the mesh")},
    {"scene", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "assembling the scene")},
    {"scene.hydrometra", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "distending the cavity")},
    {"scene.write", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "writing the package")},
    {"scope.voxelize", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "voxelizing the cavity for the scope")},
    {"scope.distance", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "measuring the room for the scope")},
    {"scope.route", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "sweeping the scope's route")},
    {"done", QT_TRANSLATE_NOOP("hs::widgets::JobStatusWidget", "done")},
};

} // namespace

QString JobStatusWidget::stepName(const QString& key) {
    // The step's own name, else its stage's ("meshing.relax.sweep" reads as relaxing the particles).
    for (QString k = key; !k.isEmpty(); k = k.left(std::max(0, int(k.lastIndexOf(QLatin1Char('.')))))) {
        for (const auto& [stepKey, name] : kStepNames)
            if (k == QLatin1String(stepKey))
                return tr(name);
        if (!k.contains(QLatin1Char('.')))
            break;
    }
    return key;
}

JobStatusWidget::JobStatusWidget(JobRunner& runner, QWidget* parent) : QWidget(parent), m_runner(runner) {
    setObjectName("jobStatus");
    m_titleLabel = new QLabel(this);
    m_titleLabel->setObjectName("jobTitleLabel");
    // Its width does not follow the step's name: a new step relays out nothing but the label.
    m_titleLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_titleLabel->setMinimumWidth(m_titleLabel->fontMetrics().averageCharWidth() * 40);
    m_progressBar = new QProgressBar(this);
    m_progressBar->setObjectName("jobProgressBar");
    m_progressBar->setRange(0, JobRunner::kProgressSteps);
    m_progressBar->setMaximumWidth(180);
    m_progressBar->setTextVisible(false);
    m_cancelButton = new QToolButton(this);
    m_cancelButton->setObjectName("jobCancelButton");
    m_cancelButton->setText(tr("Cancel"));
    m_cancelButton->setToolTip(tr("Stop the running job (Esc)"));
    m_cancelButton->setShortcut(QKeySequence(Qt::Key_Escape));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_titleLabel);
    layout->addWidget(m_progressBar);
    layout->addWidget(m_cancelButton);
    setVisible(false);

    connect(m_cancelButton, &QToolButton::clicked, &m_runner, &JobRunner::cancel);
    connect(&m_runner, &JobRunner::started, this, &JobStatusWidget::onStarted);
    connect(&m_runner, &JobRunner::progressChanged, this, &JobStatusWidget::onProgress);
    connect(&m_runner, &JobRunner::idle, this, [this] { setVisible(false); });
}

void JobStatusWidget::onStarted(const QString& title) {
    m_title = title;
    m_titleLabel->setText(title);
    m_progressBar->setValue(0);
    m_cancelButton->setEnabled(true);
    setVisible(true);
}

void JobStatusWidget::onProgress(double fraction, const QString& stageKey) {
    m_progressBar->setValue(static_cast<int>(fraction * JobRunner::kProgressSteps));
    // The pipeline's step ("meshing.relax") in the user's words beside the job's title; the key in the tooltip.
    const QString step = stepName(stageKey);
    const QString text = step.isEmpty() ? m_title : tr("%1: %2").arg(m_title, step);
    if (text != m_titleLabel->text()) // a step's many reports change nothing on the screen
        m_titleLabel->setText(text);
    m_progressBar->setToolTip(stageKey);
}

} // namespace hs::widgets
