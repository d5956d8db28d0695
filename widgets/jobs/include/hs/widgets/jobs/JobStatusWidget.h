#pragma once
/// The status bar's view of a JobRunner: what runs, how far it is (the pipeline step and a bar) and a Cancel button
/// (Esc while the window has focus). Hidden while no job runs.

#include <QWidget>

class QLabel;
class QProgressBar;
class QToolButton;

namespace hs::widgets {

class JobRunner;

class JobStatusWidget : public QWidget {
    Q_OBJECT

public:
    explicit JobStatusWidget(JobRunner& runner, QWidget* parent = nullptr);
    /// A progress step's key ("meshing.relax") in the user's language ("relaxing the particles"); an unknown step
    /// reads as its stage, an unknown stage as the key itself.
    static QString stepName(const QString& key);

private:
    void onStarted(const QString& title);
    void onProgress(double fraction, const QString& stageKey);

    JobRunner& m_runner;
    QLabel* m_titleLabel = nullptr;
    QString m_title; ///< the job's, before its step
    QProgressBar* m_progressBar = nullptr;
    QToolButton* m_cancelButton = nullptr;
};

} // namespace hs::widgets
