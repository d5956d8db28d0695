#include "hs/widgets/view/VtkView.h"

#include <QCursor>
#include <QEnterEvent>
#include <QImage>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QTimer>
#include <QWheelEvent>

#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkCommand.h>
#include <vtkDataSet.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkIntArray.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>

#include <string>

namespace hs::widgets {
namespace {

/// A press and release closer than this (logical pixels, Manhattan) is a click; farther is a drag.
constexpr int kClickTolerance = 3;
/// Qt reports wheel turns in eighths of a degree; one notch is 120.
constexpr int kWheelNotch = 120;

/// VTK's key symbols (X11 names) for the keys that have no printable text.
const char* vtkKeySym(int qtKey) {
    switch (qtKey) {
    case Qt::Key_Backspace:
        return "BackSpace";
    case Qt::Key_Tab:
        return "Tab";
    case Qt::Key_Return:
        return "Return";
    case Qt::Key_Enter:
        return "KP_Enter";
    case Qt::Key_Escape:
        return "Escape";
    case Qt::Key_Space:
        return "space";
    case Qt::Key_Delete:
        return "Delete";
    case Qt::Key_Home:
        return "Home";
    case Qt::Key_End:
        return "End";
    case Qt::Key_Left:
        return "Left";
    case Qt::Key_Up:
        return "Up";
    case Qt::Key_Right:
        return "Right";
    case Qt::Key_Down:
        return "Down";
    case Qt::Key_PageUp:
        return "Prior";
    case Qt::Key_PageDown:
        return "Next";
    case Qt::Key_Shift:
        return "Shift_L";
    case Qt::Key_Control:
        return "Control_L";
    case Qt::Key_Alt:
        return "Alt_L";
    default:
        return nullptr;
    }
}

unsigned long buttonEvent(Qt::MouseButton button, bool press) {
    switch (button) {
    case Qt::LeftButton:
        return press ? vtkCommand::LeftButtonPressEvent : vtkCommand::LeftButtonReleaseEvent;
    case Qt::MiddleButton:
        return press ? vtkCommand::MiddleButtonPressEvent : vtkCommand::MiddleButtonReleaseEvent;
    case Qt::RightButton:
        return press ? vtkCommand::RightButtonPressEvent : vtkCommand::RightButtonReleaseEvent;
    default:
        return vtkCommand::NoEvent;
    }
}

} // namespace

QSurfaceFormat VtkView::defaultFormat() {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 2);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
    format.setRedBufferSize(8);
    format.setGreenBufferSize(8);
    format.setBlueBufferSize(8);
    format.setAlphaBufferSize(8);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    format.setSamples(0); // VTK multisamples in its own framebuffers when asked to
    return format;
}

VtkView::VtkView(QWidget* parent) : QOpenGLWidget(parent) {
    qRegisterMetaType<PickResult>();
    setFormat(defaultFormat());
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setUpdateBehavior(QOpenGLWidget::NoPartialUpdate);

    m_renderWindow = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
    // Not ready until Qt has created the context in initializeGL.
    m_renderWindow->SetReadyForRendering(false);
    // VTK renders into its own framebuffers; paintGL blits the result into Qt's.
    m_renderWindow->SetFrameBlitModeToNoBlit();
    // VTK's default multisampling costs several times the frame time on a software rasterizer.
    m_renderWindow->SetMultiSamples(0);
    m_renderWindow->SetForceMaximumHardwareLineWidth(1);
    m_renderWindow->SetIsDirect(1);
    m_renderWindow->SetSupportsOpenGL(1);
    m_renderWindow->AddObserver(vtkCommand::WindowMakeCurrentEvent, this, &VtkView::onMakeCurrent);
    m_renderWindow->AddObserver(vtkCommand::WindowIsCurrentEvent, this, &VtkView::onIsCurrent);
    m_renderWindow->AddObserver(vtkCommand::WindowFrameEvent, this, &VtkView::onFrame);
    m_renderWindow->AddObserver(vtkCommand::CursorChangedEvent, this, &VtkView::onCursorChanged);

    m_renderer = vtkSmartPointer<vtkRenderer>::New();
    m_renderWindow->AddRenderer(m_renderer);

    m_interactor = vtkSmartPointer<vtkGenericRenderWindowInteractor>::New();
    m_interactor->SetRenderWindow(m_renderWindow);
    // Interactor styles call Render(); it must become a Qt update() so that VTK only renders inside paintGL.
    m_interactor->EnableRenderOff();
    m_interactor->AddObserver(vtkCommand::RenderEvent, this, &VtkView::onRenderRequest);
    m_interactor->AddObserver(vtkCommand::CreateTimerEvent, this, &VtkView::onCreateTimer);
    m_interactor->AddObserver(vtkCommand::DestroyTimerEvent, this, &VtkView::onDestroyTimer);
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    m_interactor->SetInteractorStyle(style);
    m_interactor->Initialize();

    m_picker = vtkSmartPointer<vtkCellPicker>::New();
    m_picker->SetTolerance(0.0005);
}

VtkView::~VtkView() {
    // The GL context dies in ~QOpenGLWidget, after the members: release VTK's GL objects while it is alive.
    if (context())
        disconnect(context(), nullptr, this, nullptr);
    releaseGraphics();
    for (auto& [id, timer] : m_timers)
        delete timer;
    m_timers.clear();
    m_interactor->RemoveAllObservers();
    m_renderWindow->RemoveAllObservers();
    makeCurrent(); // VTK objects may still touch GL while they are destroyed
    m_interactor->SetRenderWindow(nullptr);
    m_interactor = nullptr;
    m_picker = nullptr;
    m_renderer = nullptr;
    m_renderWindow = nullptr;
    doneCurrent();
}

vtkGenericOpenGLRenderWindow* VtkView::renderWindow() const {
    return m_renderWindow;
}

vtkGenericRenderWindowInteractor* VtkView::interactor() const {
    return m_interactor;
}

vtkRenderer* VtkView::renderer() const {
    return m_renderer;
}

void VtkView::requestRender() {
    m_needRender = true;
    update();
}

void VtkView::resetCamera() {
    m_renderer->ResetCamera();
    m_renderer->ResetCameraClippingRange();
    requestRender();
}

QImage VtkView::grabImage() {
    m_needRender = true;
    return grabFramebuffer();
}

// --- GL life cycle ------------------------------------------------------------------------------------------------

void VtkView::initializeGL() {
    // Runs with our context current; again with a new context after the widget moves to another top-level window.
    m_surface = context()->surface();
    // Qt's GL defaults differ from VTK's assumptions (GL_LESS instead of GL_LEQUAL).
    vtkOpenGLState* state = m_renderWindow->GetState();
    state->Reset();
    state->vtkglDepthFunc(GL_LEQUAL);
    // VTK does not own the context: it only initialises its function pointers and state for the current one.
    m_renderWindow->SetReadyForRendering(true);
    m_renderWindow->SetOwnContext(0);
    m_renderWindow->OpenGLInitContext();
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &VtkView::releaseGraphics,
            static_cast<Qt::ConnectionType>(Qt::DirectConnection | Qt::UniqueConnection));
    m_needRender = true;
}

void VtkView::releaseGraphics() {
    if (!context() || !m_renderWindow->GetReadyForRendering())
        return; // nothing allocated yet, or already released
    makeCurrent();
    m_renderWindow->Finalize();
    m_renderWindow->SetReadyForRendering(false);
    doneCurrent();
    m_surface = nullptr;
}

void VtkView::resizeGL(int width, int height) {
    const qreal ratio = devicePixelRatioF();
    const int pixelWidth = qRound(width * ratio);
    const int pixelHeight = qRound(height * ratio);
    // UpdateSize keeps the interactor's size (used to flip y) in step with the render window.
    m_interactor->UpdateSize(pixelWidth, pixelHeight);
    m_renderWindow->SetSize(pixelWidth, pixelHeight);
    m_renderWindow->SetDPI(qRound(72 * ratio));
    m_needRender = true;
}

void VtkView::paintGL() {
    if (!m_renderWindow->GetReadyForRendering())
        return;
    QOpenGLExtraFunctions* gl = context()->extraFunctions();
    m_inPaint = true;

    vtkOpenGLState* state = m_renderWindow->GetState();
    state->Reset();
    state->Push();
    state->vtkglDepthFunc(GL_LEQUAL);
    if (m_needRender) {
        m_renderWindow->Render();
        ++m_renderCount;
        m_needRender = false;
    }

    // Here the widget's makeCurrent is right: it binds Qt's framebuffer, the blit target.
    makeCurrent();
    const qreal ratio = devicePixelRatioF();
    const int pixelWidth = qRound(width() * ratio);
    const int pixelHeight = qRound(height() * ratio);
    gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
    const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
    gl->glDrawBuffers(1, &drawBuffer);
    gl->glDisable(GL_SCISSOR_TEST);
    const int* sourceSize = m_renderWindow->GetRenderFramebuffer()->GetLastSize();
    m_renderWindow->BlitDisplayFramebuffer(0, 0, 0, sourceSize[0], sourceSize[1], 0, 0, pixelWidth, pixelHeight,
                                           GL_COLOR_BUFFER_BIT, GL_NEAREST);

    // VTK leaves the background alpha at 0; without this the compositor would blend the view with black.
    gl->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    gl->glClearColor(0.0F, 0.0F, 0.0F, 1.0F);
    gl->glViewport(0, 0, pixelWidth, pixelHeight);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    state->Pop();
    m_inPaint = false;
}

bool VtkView::isOwnContextCurrent() const {
    const QOpenGLContext* current = QOpenGLContext::currentContext();
    return current && current == context() && current->surface() == m_surface;
}

// --- VTK -> Qt ----------------------------------------------------------------------------------------------------

void VtkView::onMakeCurrent(vtkObject*, unsigned long, void*) {
    // QOpenGLContext::makeCurrent, not QOpenGLWidget::makeCurrent: the widget's version also binds Qt's framebuffer
    // behind VTK's state cache, and VTK then attaches its textures to Qt's framebuffer (a black image).
    if (context() && m_surface)
        context()->makeCurrent(m_surface);
}

void VtkView::onIsCurrent(vtkObject*, unsigned long, void* callData) {
    *static_cast<bool*>(callData) = isOwnContextCurrent();
}

void VtkView::onFrame(vtkObject*, unsigned long, void*) {
    // A render outside paintGL (code calling Render(), vtkWindowToImageFilter): the frame is ready, only blit it.
    if (!m_inPaint) {
        m_needRender = false;
        update();
    }
}

void VtkView::onRenderRequest(vtkObject*, unsigned long, void*) {
    requestRender();
}

void VtkView::onCreateTimer(vtkObject*, unsigned long, void* callData) {
    const int vtkId = *static_cast<int*>(callData);
    QTimer*& timer = m_timers[vtkId];
    if (!timer) {
        timer = new QTimer(this);
        connect(timer, &QTimer::timeout, this, [this, vtkId] {
            if (!m_interactor->GetEnabled())
                return;
            int id = vtkId;
            m_interactor->InvokeEvent(vtkCommand::TimerEvent, &id);
            if (m_interactor->IsOneShotTimer(id))
                m_interactor->DestroyTimer(id);
        });
    }
    timer->start(static_cast<int>(m_interactor->GetTimerEventDuration()));
    m_interactor->SetTimerEventPlatformId(vtkId);
}

void VtkView::onDestroyTimer(vtkObject*, unsigned long, void* callData) {
    const auto found = m_timers.find(*static_cast<int*>(callData));
    if (found == m_timers.end())
        return;
    found->second->stop();
    found->second->deleteLater();
    m_timers.erase(found);
}

void VtkView::onCursorChanged(vtkObject*, unsigned long, void* callData) {
    switch (*static_cast<int*>(callData)) {
    case VTK_CURSOR_CROSSHAIR:
        setCursor(Qt::CrossCursor);
        break;
    case VTK_CURSOR_SIZEALL:
        setCursor(Qt::SizeAllCursor);
        break;
    case VTK_CURSOR_SIZENS:
        setCursor(Qt::SizeVerCursor);
        break;
    case VTK_CURSOR_SIZEWE:
        setCursor(Qt::SizeHorCursor);
        break;
    case VTK_CURSOR_SIZENE:
    case VTK_CURSOR_SIZESW:
        setCursor(Qt::SizeBDiagCursor);
        break;
    case VTK_CURSOR_SIZENW:
    case VTK_CURSOR_SIZESE:
        setCursor(Qt::SizeFDiagCursor);
        break;
    case VTK_CURSOR_HAND:
        setCursor(Qt::PointingHandCursor);
        break;
    default:
        unsetCursor();
        break;
    }
}

// --- Qt -> VTK ----------------------------------------------------------------------------------------------------

QPoint VtkView::toDevicePixels(const QPointF& pos) const {
    const qreal ratio = devicePixelRatioF();
    return {qRound(pos.x() * ratio), qRound(pos.y() * ratio)};
}

void VtkView::setEventPosition(const QPointF& pos, Qt::KeyboardModifiers modifiers, int repeatCount) {
    const QPoint p = toDevicePixels(pos);
    m_interactor->SetEventInformationFlipY(p.x(), p.y(), modifiers.testFlag(Qt::ControlModifier) ? 1 : 0,
                                           modifiers.testFlag(Qt::ShiftModifier) ? 1 : 0, 0, repeatCount);
    m_interactor->SetAltKey(modifiers.testFlag(Qt::AltModifier) ? 1 : 0);
}

void VtkView::forwardMouseButton(QMouseEvent* event, bool press, int repeatCount) {
    setEventPosition(event->position(), event->modifiers(), repeatCount);
    const unsigned long vtkEvent = buttonEvent(event->button(), press);
    if (vtkEvent != vtkCommand::NoEvent)
        m_interactor->InvokeEvent(vtkEvent, event);
    event->accept();
}

void VtkView::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton) {
        m_pressPos = event->position().toPoint();
        m_clickCandidate = true;
    }
    forwardMouseButton(event, true, 0);
}

void VtkView::mouseDoubleClickEvent(QMouseEvent* event) {
    // VTK reads a double click as a press with repeat count 1.
    forwardMouseButton(event, true, 1);
}

void VtkView::mouseReleaseEvent(QMouseEvent* event) {
    forwardMouseButton(event, false, 0);
    if (event->button() == Qt::LeftButton && m_clickCandidate) {
        m_clickCandidate = false;
        emit picked(pickAt(event->position().toPoint()));
    }
}

void VtkView::mouseMoveEvent(QMouseEvent* event) {
    if (m_clickCandidate && (event->position().toPoint() - m_pressPos).manhattanLength() > kClickTolerance)
        m_clickCandidate = false; // a drag, not a click
    setEventPosition(event->position(), event->modifiers());
    m_interactor->InvokeEvent(vtkCommand::MouseMoveEvent, event);
    event->accept();
}

void VtkView::wheelEvent(QWheelEvent* event) {
    setEventPosition(event->position(), event->modifiers());
    // One VTK wheel event per notch; touchpads send small deltas that add up.
    const QPoint delta = event->angleDelta();
    m_wheelAccumulator += delta.y() != 0 ? delta.y() : delta.x();
    for (; m_wheelAccumulator >= kWheelNotch; m_wheelAccumulator -= kWheelNotch)
        m_interactor->InvokeEvent(vtkCommand::MouseWheelForwardEvent, event);
    for (; m_wheelAccumulator <= -kWheelNotch; m_wheelAccumulator += kWheelNotch)
        m_interactor->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, event);
    event->accept();
}

void VtkView::forwardKey(QKeyEvent* event, bool press) {
    const QString text = event->text();
    const char keyCode = text.isEmpty() ? '\0' : text.at(0).toLatin1();
    const char* symbol = vtkKeySym(event->key());
    const std::string keySym =
        symbol ? std::string(symbol) : (text.isEmpty() ? std::string("None") : text.toStdString());
    const Qt::KeyboardModifiers modifiers = event->modifiers();
    const int control = modifiers.testFlag(Qt::ControlModifier) ? 1 : 0;
    const int shift = modifiers.testFlag(Qt::ShiftModifier) ? 1 : 0;
    if (press) {
        const QPoint p = toDevicePixels(mapFromGlobal(QCursor::pos()));
        m_interactor->SetEventInformationFlipY(p.x(), p.y(), control, shift, keyCode, event->count(), keySym.c_str());
        m_interactor->SetAltKey(modifiers.testFlag(Qt::AltModifier) ? 1 : 0);
        m_interactor->InvokeEvent(vtkCommand::KeyPressEvent, event);
        m_interactor->InvokeEvent(vtkCommand::CharEvent, event);
    } else {
        m_interactor->SetKeyEventInformation(control, shift, keyCode, event->count(), keySym.c_str());
        m_interactor->InvokeEvent(vtkCommand::KeyReleaseEvent, event);
    }
    event->accept();
}

void VtkView::keyPressEvent(QKeyEvent* event) {
    forwardKey(event, true);
}

void VtkView::keyReleaseEvent(QKeyEvent* event) {
    forwardKey(event, false);
}

void VtkView::enterEvent(QEnterEvent* event) {
    setEventPosition(event->position(), event->modifiers());
    m_interactor->InvokeEvent(vtkCommand::EnterEvent, event);
}

void VtkView::leaveEvent(QEvent* event) {
    m_interactor->InvokeEvent(vtkCommand::LeaveEvent, event);
}

// --- Picking ------------------------------------------------------------------------------------------------------

PickResult VtkView::pickAt(const QPoint& pos) const {
    const QPoint p = toDevicePixels(pos);
    const int pixelHeight = qRound(height() * devicePixelRatioF());
    PickResult result;
    // vtkCellPicker casts the ray on the CPU, against the actors' data: no GL context is needed.
    result.hit = m_picker->Pick(p.x(), pixelHeight - 1 - p.y(), 0.0, m_renderer) != 0;
    if (result.hit) {
        const double* position = m_picker->GetPickPosition();
        result.point = QVector3D(static_cast<float>(position[0]), static_cast<float>(position[1]),
                                 static_cast<float>(position[2]));
        result.cellId = static_cast<qint64>(m_picker->GetCellId());
        result.prop = m_picker->GetViewProp();
        // The region label of the cell hit, as the mesh displays carry it through their filters.
        if (vtkDataSet* picked = m_picker->GetDataSet(); picked && result.cellId >= 0)
            if (auto* regions = vtkIntArray::SafeDownCast(picked->GetCellData()->GetArray("region"));
                regions && result.cellId < regions->GetNumberOfTuples())
                result.region = regions->GetValue(static_cast<vtkIdType>(result.cellId));
    }
    return result;
}

} // namespace hs::widgets
