#pragma once
/// The simulator's window: the endoscopic view with its heads-up display, menus (File, Scope, Exercise, Help), and
/// the scope under the keyboard and mouse when no device is given. A trial runs from the moment its package is
/// loaded: a physics thread (PhysicsLoop) steps the world from the device's samples while the window draws the
/// newest frame at display rate. Ending the trial writes the report (JSON and page) and the trial file.

#include "hs/sim/World.h"
#include "hs/simapp/PhysicsLoop.h"
#include "hs/simapp/SampleSource.h"
#include "hs/simapp/SimOptions.h"
#include "hs/simrender/EndoscopicView.h"

#include <QElapsedTimer>
#include <QImage>
#include <QMainWindow>

#include <memory>
#include <string>
#include <vector>

class QActionGroup;
class QLabel;
class QTimer;

namespace hs::widgets {
class VtkView;
}

namespace hs::simapp {

class SimWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit SimWindow(SimOptions options, QWidget* parent = nullptr);
    ~SimWindow() override;

    /// Loads the package on a worker thread and starts a trial; sessionStarted() or loadFailed() follows.
    void openPackage(const QString& folder);
    /// Ends the running trial and writes its report to `jsonPath`, the page beside it (.html) and the trial file
    /// (--record's path, else beside the report, .trial). False with a message box when writing failed.
    bool endTrial(const QString& jsonPath);
    bool isRunning() const;

    widgets::VtkView* view() const { return m_view; }
    /// The keyboard and mouse source (null when a script or a trial drives the scope).
    KeyboardSource* keyboard() const { return m_keyboard; }
    const sim::World* world() const { return m_world.get(); }
    /// The newest state drawn.
    const sim::WorldState& drawnState() const { return m_drawn; }
    int framesDrawn() const { return m_framesDrawn; }
    /// The endoscopic view's image (rendered now).
    QImage grabView();

    /// Keys, as the help dialog lists them.
    static QString keyHelp();

signals:
    void sessionStarted();
    void loadFailed(const QString& message);
    void trialEnded(const QString& reportPath);
    void sourceEnded();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

private:
    void buildMenus();
    void startSession(std::unique_ptr<sim::World> world);
    void stopSession();
    void restartWithOptions();
    void onRenderTick();
    void onOpenPackage();
    void onEndTrial();
    void onShowKeys();
    bool handleKey(QKeyEvent* event, bool press);
    QString defaultReportPath() const;

    SimOptions m_options;
    widgets::VtkView* m_view = nullptr;
    std::unique_ptr<simrender::EndoscopicView> m_endoscope;
    QLabel* m_statusLabel = nullptr;
    QTimer* m_renderTimer = nullptr;
    QActionGroup* m_opticGroup = nullptr;
    QActionGroup* m_diameterGroup = nullptr;
    QActionGroup* m_exerciseGroup = nullptr;

    std::unique_ptr<sim::World> m_world;
    std::unique_ptr<SampleSource> m_source;
    KeyboardSource* m_keyboard = nullptr; ///< m_source when the keyboard drives
    HapticsSource* m_haptics = nullptr;   ///< m_source when a haptic device drives
    sim::Trial m_replay;                  ///< --replay's trial (TrialSource reads it)
    std::unique_ptr<PhysicsLoop> m_loop;
    std::string m_startedUtc;
    bool m_loading = false;

    std::vector<Vec3> m_visualPoints;
    sim::WorldState m_drawn;
    int m_framesDrawn = 0;
    QElapsedTimer m_hudClock;     ///< since the heads-up text was last set
    std::string m_hudWarning;     ///< its warning line then
    QElapsedTimer m_sessionClock; ///< since the session started: its mean frame rate, logged when the samples end
    int m_sessionFrames = 0;
    QElapsedTimer m_fpsClock;
    std::uint64_t m_drawnCutEvents = 0; ///< the cut events the view hides the faces of
    int m_fpsFrames = 0;
    double m_fps = 0.0;
    bool m_rendererLogged = false; ///< the GL renderer and the view's detail, logged once
    QPoint m_dragFrom;
    bool m_dragging = false;
};

} // namespace hs::simapp
