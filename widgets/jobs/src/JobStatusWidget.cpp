#include "hs/widgets/jobs/JobStatusWidget.h"

#include "hs/widgets/jobs/JobRunner.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QToolButton>

namespace hs::widgets {

JobStatusWidget::JobStatusWidget(JobRunner& runner, QWidget* parent) : QWidget(parent), m_runner(runner) {
    setObjectName("jobStatus");
    m_titleLabel = new QLabel(this);
    m_titleLabel->setObjectName("jobTitleLabel");
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
    m_titleLabel->setText(title);
    m_progressBar->setValue(0);
    m_cancelButton->setEnabled(true);
    setVisible(true);
}

void JobStatusWidget::onProgress(double fraction, const QString& stageKey) {
    m_progressBar->setValue(static_cast<int>(fraction * JobRunner::kProgressSteps));
    // The pipeline's step key ("meshing.relax"): the stage's name is what the user recognises.
    m_progressBar->setToolTip(stageKey);
}

} // namespace hs::widgets
