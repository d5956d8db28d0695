// The simulator's window: loading a package off the GUI thread, the physics thread, drawing the newest frame at
// display rate, the keyboard and mouse as a device, and the end of a trial with its report.
#include "hs/simapp/SimWindow.h"

#include "hs/haptics/HidDevice.h"

#include "hs/simapp/Headless.h"
#include "hs/simrender/Hud.h"
#include "hs/widgets/common/FileDialog.h"
#include "hs/widgets/common/MessageBox.h"
#include "hs/widgets/view/VtkView.h"

#include <QActionGroup>
#include <QCloseEvent>
#include <QDateTime>
#include <QDesktopServices>
#include <QDir>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QKeyEvent>
#include <QLabel>
#include <QMenuBar>
#include <QStatusBar>
#include <QTimer>
#include <QUrl>
#include <QtConcurrent>

#include <vtkRenderer.h>

namespace hs::simapp {

namespace {

using widgets::FileDialog;
using widgets::MessageBox;

/// Degrees of pivot per pixel of mouse drag, and mm of insertion per wheel step (120 units).
constexpr double kDragDegPerPixel = 0.15;
constexpr double kWheelMm = 1.0;
constexpr int kRenderIntervalMs = 15;
/// The heads-up text's refresh, ms (4 a second: readable, like a pump's display).
constexpr int kHudIntervalMs = 250;

struct LoadOutcome {
    std::unique_ptr<sim::World> world;
    std::optional<Error> error;
};

QString fromUtf8(const std::string& text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

std::string toUtf8(const QString& text) {
    return text.toUtf8().toStdString();
}

/// The endoscopic view's size when the window opens, pixels.
constexpr int kDefaultViewWidth = 640;
constexpr int kDefaultViewHeight = 480;

} // namespace

SimWindow::SimWindow(SimOptions options, QWidget* parent) : QMainWindow(parent), m_options(std::move(options)) {
    setObjectName("simWindow");
    setWindowTitle(tr("hysteroscene simulator"));
    m_view = new widgets::VtkView(this);
    m_view->setObjectName("endoscopeView");
    m_view->setMinimumSize(320, 240);
    m_view->setFocusPolicy(Qt::StrongFocus);
    m_view->installEventFilter(this);
    setCentralWidget(m_view);
    m_endoscope = std::make_unique<simrender::EndoscopicView>(m_view->renderer());
    m_statusLabel = new QLabel(tr("Open a scene package (File > Open)."), this);
    m_statusLabel->setObjectName("simStatusLabel");
    statusBar()->addWidget(m_statusLabel, 1);
    buildMenus();
    m_renderTimer = new QTimer(this);
    m_renderTimer->setInterval(kRenderIntervalMs);
    connect(m_renderTimer, &QTimer::timeout, this, &SimWindow::onRenderTick);
    // The view opens at 640 x 480 (a standard-definition endoscopy camera's picture), where the endoscopic view
    // keeps 30 frames per second even on a software GL renderer (docs/simulator.md, "Endoscopic view"); the window
    // can be made larger.
    resize(kDefaultViewWidth, kDefaultViewHeight + menuBar()->sizeHint().height() + statusBar()->sizeHint().height());
}

SimWindow::~SimWindow() {
    stopSession();
}

void SimWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open Package..."), this, &SimWindow::onOpenPackage);
    open->setObjectName("actionOpenPackage");
    open->setShortcut(QKeySequence::Open);
    QAction* end = file->addAction(tr("&End Trial and Show Report..."), this, &SimWindow::onEndTrial);
    end->setObjectName("actionEndTrial");
    end->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    QAction* restart = file->addAction(tr("&Restart Trial"), this, &SimWindow::restartWithOptions);
    restart->setObjectName("actionRestartTrial");
    restart->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setObjectName("actionQuit");
    quit->setShortcut(QKeySequence::Quit);

    // Changing the scope or the exercise starts a new trial: a trial's settings are fixed (its header).
    const auto choices = [this](QMenu* menu, const QList<QPair<QString, double>>& items, double current,
                                const char* name) {
        auto* group = new QActionGroup(this);
        for (const auto& [text, value] : items) {
            QAction* action = menu->addAction(text);
            action->setCheckable(true);
            action->setData(value);
            action->setObjectName(QString("%1-%2").arg(name).arg(value));
            action->setChecked(value == current);
            group->addAction(action);
        }
        connect(group, &QActionGroup::triggered, this, [this] { restartWithOptions(); });
        return group;
    };
    QMenu* scope = menuBar()->addMenu(tr("&Scope"));
    QMenu* optic = scope->addMenu(tr("&Optic"));
    m_opticGroup = choices(optic, {{tr("0°"), 0.0}, {tr("12°"), 12.0}, {tr("30°"), 30.0}},
                           m_options.world.scope.opticDeg, "actionOptic");
    QMenu* diameter = scope->addMenu(tr("&Diameter"));
    m_diameterGroup = choices(diameter, {{tr("2.9 mm"), 2.9}, {tr("4 mm"), 4.0}, {tr("5 mm"), 5.0}},
                              m_options.world.scope.diameterMm, "actionDiameter");
    QMenu* exercise = menuBar()->addMenu(tr("&Exercise"));
    m_exerciseGroup = choices(
        exercise,
        {{tr("&Exploration: see the fundus, both ostia and every wall"),
          double(static_cast<int>(sim::Exercise::Exploration))},
         {tr("&Diagnosis: mark each pathology"), double(static_cast<int>(sim::Exercise::Diagnosis))},
         {tr("&Polypectomy: resect the polyps with the loop"), double(static_cast<int>(sim::Exercise::Polypectomy))},
         {tr("&Myomectomy: resect the submucous myomas with the loop"),
          double(static_cast<int>(sim::Exercise::Myomectomy))}},
        double(static_cast<int>(m_options.world.exercise)), "actionExercise");
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* keys = help->addAction(tr("&Keys..."), this, &SimWindow::onShowKeys);
    keys->setObjectName("actionKeys");
    keys->setShortcut(QKeySequence::HelpContents);
}

QString SimWindow::keyHelp() {
    return tr("<table>"
              "<tr><td>Arrow keys, or drag with the mouse</td><td>turn the scope about the cervix (pitch, "
              "yaw)</td></tr>"
              "<tr><td>W / S, or the mouse wheel</td><td>insert / withdraw</td></tr>"
              "<tr><td>Q / E</td><td>roll the scope (an oblique optic looks round)</td></tr>"
              "<tr><td>Z / X</td><td>roll the camera head (the image's horizon)</td></tr>"
              "<tr><td>I / O</td><td>open or close the inflow / outflow valve</td></tr>"
              "<tr><td>Space</td><td>mark the pathology at the centre of the view</td></tr>"
              "<tr><td>Ctrl+E</td><td>end the trial and show the report</td></tr>"
              "<tr><td>Ctrl+R</td><td>restart the trial</td></tr>"
              "<tr><td>F1</td><td>this help</td></tr></table>") +
           tr("<p>The instruments (polypectomy, myomectomy) and the pump:</p><table>"
              "<tr><td>L</td><td>the next instrument: the resectoscope's loop, scissors, grasper, none</td></tr>"
              "<tr><td>R / F</td><td>push the instrument out / draw it in (the working element)</td></tr>"
              "<tr><td>C, held</td><td>the cutting pedal (scissors and grasper: close the jaws)</td></tr>"
              "<tr><td>V, held</td><td>the coagulating pedal</td></tr>"
              "<tr><td>+ / -</td><td>raise / lower the pump's set pressure by 5 mmHg</td></tr></table>");
}

void SimWindow::onShowKeys() {
    MessageBox::information(this, tr("Keys"), keyHelp());
}

void SimWindow::openPackage(const QString& folder) {
    stopSession();
    m_options.scene = toUtf8(folder);
    m_loading = true;
    m_statusLabel->setText(tr("Loading %1...").arg(QDir::toNativeSeparators(folder)));
    auto* watcher = new QFutureWatcher<std::shared_ptr<LoadOutcome>>(this);
    connect(watcher, &QFutureWatcher<std::shared_ptr<LoadOutcome>>::finished, this, [this, watcher] {
        watcher->deleteLater();
        m_loading = false;
        std::shared_ptr<LoadOutcome> outcome = watcher->result();
        if (outcome->error) {
            const QString message = fromUtf8(outcome->error->message());
            m_statusLabel->setText(tr("The package could not be loaded."));
            MessageBox::critical(this, tr("Open Package"), tr("The scene package could not be loaded."), message);
            emit loadFailed(message);
            return;
        }
        startSession(std::move(outcome->world));
    });
    const SimOptions options = m_options;
    watcher->setFuture(QtConcurrent::run([options] {
        auto outcome = std::make_shared<LoadOutcome>();
        auto world = sim::World::load(options.scene, options.world);
        if (world)
            outcome->world = std::move(*world);
        else
            outcome->error = world.error();
        return outcome;
    }));
}

void SimWindow::startSession(std::unique_ptr<sim::World> world) {
    m_world = std::move(world);
    m_keyboard = nullptr;
    m_haptics = nullptr;
    if (!m_options.replayPath.empty()) {
        auto trial = sim::readTrial(m_options.replayPath);
        if (!trial) {
            MessageBox::critical(this, tr("Replay"), tr("The trial could not be read."),
                                 fromUtf8(trial.error().message()));
            emit loadFailed(fromUtf8(trial.error().message()));
            return;
        }
        // A trial replays bit for bit only on the physics and settings that recorded it.
        if (Status same = sim::checkReplay(trial->header, m_world->options()); !same) {
            MessageBox::critical(this, tr("Replay"), tr("The trial was recorded with other settings."),
                                 fromUtf8(same.error().message()));
            emit loadFailed(fromUtf8(same.error().message()));
            return;
        }
        m_replay = std::move(*trial);
        m_source = std::make_unique<TrialSource>(m_replay);
    } else if (m_options.device.kind == DeviceSpec::Kind::Demo) {
        auto script = sim::demonstrationScript(*m_world);
        if (!script) {
            MessageBox::critical(this, tr("Demonstration"), tr("The demonstration could not be planned."),
                                 fromUtf8(script.error().message()));
            emit loadFailed(fromUtf8(script.error().message()));
            return;
        }
        m_source = std::make_unique<ScriptSource>(std::move(*script));
    } else if (m_options.device.kind == DeviceSpec::Kind::Scripted) {
        auto script = sim::readScript(m_options.device.scriptPath);
        if (!script) {
            MessageBox::critical(this, tr("Script"), tr("The script could not be read."),
                                 fromUtf8(script.error().message()));
            emit loadFailed(fromUtf8(script.error().message()));
            return;
        }
        m_source = std::make_unique<ScriptSource>(std::move(*script));
    } else if (m_options.device.kind == DeviceSpec::Kind::Hid) {
        haptics::HidDeviceOptions hid;
        if (m_options.device.vendorId != 0 || m_options.device.productId != 0) {
            hid.vendorId = m_options.device.vendorId;
            hid.productId = m_options.device.productId;
        }
        auto source = HapticsSource::start(std::make_unique<haptics::HidDevice>(hid));
        if (!source) {
            MessageBox::critical(this, tr("Haptic device"), tr("The haptic hysteroscope could not be opened."),
                                 fromUtf8(source.error().message()));
            emit loadFailed(fromUtf8(source.error().message()));
            return;
        }
        m_haptics = source->get();
        m_source = std::move(*source);
        if (sim::isOperative(m_world->options().exercise) && !m_haptics->deviceLimits().resectoscope)
            MessageBox::information(
                this, tr("Haptic device"),
                tr("This device speaks version 1 of the hysteroscope protocol: it drives the diagnostic scope only. "
                   "The resectoscope's loop, pedals and pump buttons need a device of version 2 "
                   "(docs/haptics-protocol.md); without one the %1 exercise cannot cut.")
                    .arg(fromUtf8(std::string(sim::toString(m_world->options().exercise)))));
    } else {
        auto keyboard = std::make_unique<KeyboardSource>();
        if (sim::isOperative(m_world->options().exercise))
            keyboard->setInstrument(sim::kInstrumentLoop); // the resectoscope in hand (L exchanges it)
        m_keyboard = keyboard.get();
        m_source = std::move(keyboard);
    }
    m_endoscope->setSurface(m_world->scene().surface);
    m_startedUtc = utcNow();
    m_loop = std::make_unique<PhysicsLoop>(*m_world, *m_source);
    if (m_haptics) {
        HapticsSource* haptic = m_haptics;
        haptic->publish(m_world->hapticFrame());
        m_loop->setAfterStep([haptic](const sim::World& stepped) { haptic->publish(stepped.hapticFrame()); });
    }
    m_loop->start();
    m_fpsClock.start();
    m_sessionClock.start();
    m_hudClock.invalidate();
    m_sessionFrames = 0;
    m_fpsFrames = 0;
    m_renderTimer->start();
    m_view->setFocus();
    setWindowTitle(tr("hysteroscene simulator: %1").arg(QFileInfo(fromUtf8(m_options.scene)).fileName()));
    emit sessionStarted();
}

void SimWindow::stopSession() {
    if (m_haptics)
        m_haptics->cancel();
    if (m_loop)
        m_loop->stop();
    m_renderTimer->stop();
}

bool SimWindow::isRunning() const {
    return m_loop && m_loop->running();
}

void SimWindow::restartWithOptions() {
    m_options.world.scope.opticDeg = m_opticGroup->checkedAction()->data().toDouble();
    m_options.world.scope.diameterMm = m_diameterGroup->checkedAction()->data().toDouble();
    m_options.world.exercise =
        static_cast<sim::Exercise>(static_cast<int>(m_exerciseGroup->checkedAction()->data().toDouble()));
    if (!m_options.scene.empty() && !m_loading)
        openPackage(fromUtf8(m_options.scene));
}

void SimWindow::onRenderTick() {
    if (!m_loop)
        return;
    if (std::optional<Frame> frame = m_loop->takeFrame()) {
        const sim::WorldState& state = frame->snapshot.state;
        // Visibility first: the points of the outer surface are moved only while it is drawn.
        m_endoscope->setOuterSurfaceVisible(state.sample.insertionMm < 0.0 || state.contact.perforated);
        m_world->visualPoints(frame->snapshot.simulationPointsMm, m_visualPoints, m_endoscope->sourcePointsInUse());
        m_endoscope->setPoints(m_visualPoints);
        m_endoscope->setPose(simrender::cameraPose(state.scope, m_options.world.scope));
        m_endoscope->setFluid(state.fluid.turbidity, state.fluid.redOut, state.blood.mixedFraction);
        m_endoscope->setBloodClouds(state.blood);
        // The cut: the visual surface's faces in removed tets hide (anew once per cut event), the bared faces and
        // the loop are drawn.
        const sim::CutView* cut = frame->snapshot.cut.get();
        const std::uint64_t cutEvents = cut ? cut->events : 0;
        if (cutEvents != m_drawnCutEvents) {
            m_endoscope->setHiddenPoints(m_world->visualPointsCut(cut));
            m_drawnCutEvents = cutEvents;
        }
        m_endoscope->setChips(frame->snapshot.chips);
        if (cut)
            m_endoscope->setCutSurface(frame->snapshot.simulationPointsMm, m_world->simulationMesh().points, cut->faces,
                                       cut->faceTissue);
        else
            m_endoscope->setCutSurface({}, {}, {}, {});
        m_endoscope->setLoop(state.loop);
        m_endoscope->setTime(state.timeS); // the camera adapts on the trial's clock
        // The heads-up text is redrawn a few times a second (its glyphs cost a third of the GUI thread's time when
        // drawn every frame on a software GL renderer), at once when its warning line changes.
        const simrender::HudText hud = simrender::hudText(state, m_options.world.fluid, frame->progress);
        if (!m_hudClock.isValid() || m_hudClock.elapsed() >= kHudIntervalMs || hud.warning != m_hudWarning) {
            m_endoscope->setHud(hud);
            m_hudWarning = hud.warning;
            m_hudClock.start();
        }
        m_drawn = state;
        m_view->requestRender();
        ++m_framesDrawn;
        ++m_sessionFrames;
        ++m_fpsFrames;
    }
    if (m_fpsClock.elapsed() >= 1000) {
        m_fps = m_fpsFrames * 1000.0 / static_cast<double>(m_fpsClock.restart());
        m_fpsFrames = 0;
        // On a software rasterizer the view draws its light detail (docs/simulator.md, "Endoscopic view").
        const QString detail = m_endoscope->lightDetail() ? tr(" (light view: software GL)") : QString();
        if (!m_rendererLogged && !m_endoscope->glRenderer().empty()) {
            m_rendererLogged = true;
            qInfo("endoscopic view: GL renderer %s, %s detail (%zu triangles)", m_endoscope->glRenderer().c_str(),
                  m_endoscope->lightDetail() ? "light" : "full", m_endoscope->drawnTriangleCount());
        }
        m_statusLabel->setText(tr("%L1 fps%4, physics %L2 steps/s, insertion %L3 mm")
                                   .arg(m_fps, 0, 'f', 0)
                                   .arg(m_loop->stepsPerSecond(), 0, 'f', 0)
                                   .arg(m_drawn.sample.insertionMm, 0, 'f', 1)
                                   .arg(detail));
    }
    if (m_loop->finished()) {
        m_renderTimer->stop();
        if (const auto error = m_loop->error())
            MessageBox::critical(this, tr("Simulation"), tr("The simulation stopped."), fromUtf8(error->message()));
        m_statusLabel->setText(tr("The device's samples have ended: File > End Trial shows the report."));
        const double seconds = static_cast<double>(m_sessionClock.elapsed()) / 1000.0;
        qInfo("endoscopic view: %d frames in %.1f s, %.1f fps at %d x %d, %s detail", m_sessionFrames, seconds,
              seconds > 0.0 ? m_sessionFrames / seconds : 0.0, m_view->width(), m_view->height(),
              m_endoscope->lightDetail() ? "light" : "full");
        emit sourceEnded();
    }
}

QString SimWindow::defaultReportPath() const {
    const QString stamp = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss"));
    const QFileInfo scene(fromUtf8(m_options.scene));
    return scene.absoluteDir().filePath(QStringLiteral("trial-%1-%2.json").arg(scene.fileName(), stamp));
}

void SimWindow::onEndTrial() {
    if (!m_world)
        return;
    QString path = fromUtf8(m_options.reportPath);
    if (path.isEmpty())
        path = FileDialog::getSaveFileName(this, tr("Save the Trial's Report"), defaultReportPath(),
                                           tr("Trial reports (*.json)"));
    if (path.isEmpty())
        return;
    if (!endTrial(path))
        return;
    QString html = path;
    html.replace(QRegularExpression(QStringLiteral("\\.json$")), QString());
    html += QStringLiteral(".html");
    if (MessageBox::askYesNo(this, tr("Trial Report"),
                             tr("The report is in %1. Open it?").arg(QDir::toNativeSeparators(html))) ==
        MessageBox::Choice::Yes)
        QDesktopServices::openUrl(QUrl::fromLocalFile(html));
}

bool SimWindow::endTrial(const QString& jsonPath) {
    if (!m_world)
        return false;
    stopSession();
    sim::Trial trial;
    trial.header = m_world->trialHeader();
    trial.header.device = m_options.replayPath.empty() ? m_options.device.text() : m_replay.header.device;
    trial.header.startedUtc = m_options.replayPath.empty() ? m_startedUtc : m_replay.header.startedUtc;
    sim::TrialReport report = m_world->report();
    report.header = trial.header;
    QString base = jsonPath;
    base.replace(QRegularExpression(QStringLiteral("\\.json$")), QString());
    const std::string html = toUtf8(base + QStringLiteral(".html"));
    const std::string trialPath =
        m_options.recordPath.empty() ? toUtf8(base + QStringLiteral(".trial")) : m_options.recordPath;
    Status written = sim::writeReport(report, toUtf8(jsonPath), html);
    if (written && m_options.replayPath.empty() && m_loop) {
        trial.samples = m_loop->samples();
        written = sim::writeTrial(trial, trialPath);
    }
    if (!written) {
        MessageBox::critical(this, tr("Trial Report"), tr("The report could not be written."),
                             fromUtf8(written.error().message()));
        return false;
    }
    m_statusLabel->setText(tr("Trial ended; report written to %1.").arg(QDir::toNativeSeparators(jsonPath)));
    emit trialEnded(jsonPath);
    return true;
}

void SimWindow::onOpenPackage() {
    const QString folder = FileDialog::getExistingDirectory(this, tr("Open a Scene Package"),
                                                            QFileInfo(fromUtf8(m_options.scene)).absolutePath());
    if (!folder.isEmpty())
        openPackage(folder);
}

QImage SimWindow::grabView() {
    return m_view->grabImage();
}

void SimWindow::closeEvent(QCloseEvent* event) {
    stopSession();
    QMainWindow::closeEvent(event);
}

bool SimWindow::handleKey(QKeyEvent* event, bool press) {
    if (!m_keyboard)
        return false;
    using Axis = KeyboardSource::Axis;
    const int held = press ? 1 : 0;
    switch (event->key()) {
    case Qt::Key_Up:
        m_keyboard->setHeld(Axis::Pitch, held);
        return true;
    case Qt::Key_Down:
        m_keyboard->setHeld(Axis::Pitch, -held);
        return true;
    case Qt::Key_Left:
        m_keyboard->setHeld(Axis::Yaw, held);
        return true;
    case Qt::Key_Right:
        m_keyboard->setHeld(Axis::Yaw, -held);
        return true;
    case Qt::Key_W:
        m_keyboard->setHeld(Axis::Insertion, held);
        return true;
    case Qt::Key_S:
        m_keyboard->setHeld(Axis::Insertion, -held);
        return true;
    case Qt::Key_Q:
        m_keyboard->setHeld(Axis::Roll, -held);
        return true;
    case Qt::Key_E:
        m_keyboard->setHeld(Axis::Roll, held);
        return true;
    case Qt::Key_Z:
        m_keyboard->setHeld(Axis::CameraRoll, -held);
        return true;
    case Qt::Key_X:
        m_keyboard->setHeld(Axis::CameraRoll, held);
        return true;
    case Qt::Key_I:
        if (press)
            m_keyboard->toggleInflow();
        return true;
    case Qt::Key_O:
        if (press)
            m_keyboard->toggleOutflow();
        return true;
    case Qt::Key_Space:
        if (press)
            m_keyboard->mark();
        return true;
    // The resectoscope (operative exercises): the working element, the pedals, the instrument; the pump.
    case Qt::Key_R:
        m_keyboard->setHeld(Axis::WorkingElement, held);
        return true;
    case Qt::Key_F:
        m_keyboard->setHeld(Axis::WorkingElement, -held);
        return true;
    case Qt::Key_C:
        m_keyboard->setButtonHeld(sim::kButtonCut, press);
        return true;
    case Qt::Key_V:
        m_keyboard->setButtonHeld(sim::kButtonCoagulate, press);
        return true;
    case Qt::Key_L:
        if (press)
            m_keyboard->setInstrument(sim::nextInstrument(m_keyboard->current().instrument));
        return true;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        if (press)
            m_keyboard->press(sim::kButtonPumpUp);
        return true;
    case Qt::Key_Minus:
        if (press)
            m_keyboard->press(sim::kButtonPumpDown);
        return true;
    default:
        return false;
    }
}

bool SimWindow::eventFilter(QObject* watched, QEvent* event) {
    if (watched != m_view)
        return QMainWindow::eventFilter(watched, event);
    // The view's own camera interaction is off: keys and the mouse drive the scope.
    switch (event->type()) {
    case QEvent::KeyPress:
    case QEvent::KeyRelease: {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->isAutoRepeat())
            return true;
        return handleKey(key, event->type() == QEvent::KeyPress);
    }
    case QEvent::MouseButtonPress:
        m_dragFrom = static_cast<QMouseEvent*>(event)->position().toPoint();
        m_dragging = true;
        return true;
    case QEvent::MouseMove:
        if (m_dragging && m_keyboard) {
            const QPoint at = static_cast<QMouseEvent*>(event)->position().toPoint();
            const QPoint delta = at - m_dragFrom;
            m_dragFrom = at;
            m_keyboard->nudge(KeyboardSource::Axis::Pitch, -delta.y() * kDragDegPerPixel);
            m_keyboard->nudge(KeyboardSource::Axis::Yaw, -delta.x() * kDragDegPerPixel);
        }
        return true;
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
        m_dragging = false;
        return true;
    case QEvent::Wheel:
        if (m_keyboard)
            m_keyboard->nudge(KeyboardSource::Axis::Insertion,
                              static_cast<QWheelEvent*>(event)->angleDelta().y() / 120.0 * kWheelMm);
        return true;
    default:
        return QMainWindow::eventFilter(watched, event);
    }
}

} // namespace hs::simapp
