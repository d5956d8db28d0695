#pragma once
/// A Qt6 QOpenGLWidget that hosts a VTK render window, built on VTK's core modules only (Debian's VTK Qt module is
/// built against Qt5). VTK renders into its own framebuffers inside paintGL; the widget blits the result into Qt's.

#include <QOpenGLWidget>
#include <QPoint>
#include <QSurfaceFormat>
#include <QVector3D>

#include <vtkSmartPointer.h>

#include <cstdint>
#include <map>

class QImage;
class QSurface;
class QTimer;
class vtkCellPicker;
class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkObject;
class vtkProp;
class vtkRenderer;

namespace hs::widgets {

/// Where a click landed: a point on a visible surface (world coordinates, mm) or nothing.
struct PickResult {
    bool hit = false;
    QVector3D point;          ///< world position of the hit; zero on a miss
    qint64 cellId = -1;       ///< cell of the picked actor's input; -1 on a miss
    vtkProp* prop = nullptr;  ///< the actor hit; nullptr on a miss
    std::int32_t region = -1; ///< the "region" label of the cell hit; -1 on a miss or a mesh without labels
};

class VtkView : public QOpenGLWidget {
    Q_OBJECT

public:
    explicit VtkView(QWidget* parent = nullptr);
    ~VtkView() override;
    VtkView(const VtkView&) = delete;
    VtkView& operator=(const VtkView&) = delete;

    /// OpenGL 3.2 core, RGBA8, depth 24, stencil 8, no multisampling. Set it as the application's default format
    /// before QApplication exists: every QOpenGLWidget of a window shares contexts with the window's compositor.
    static QSurfaceFormat defaultFormat();

    vtkGenericOpenGLRenderWindow* renderWindow() const;
    vtkGenericRenderWindowInteractor* interactor() const;
    /// The view's one renderer; add actors here (one actor per view: VTK actors cannot be shared between views).
    vtkRenderer* renderer() const;

    /// Schedules a VTK render on the next paint.
    void requestRender();
    /// Fits the camera to the visible props and re-renders.
    void resetCamera();

    /// Casts a ray through `pos` (logical pixels, origin top-left) on the CPU; needs no GL context.
    PickResult pickAt(const QPoint& pos) const;

    /// The widget's current image, rendered if needed (for tests and screenshots).
    QImage grabImage();

    /// Number of VTK renders so far (tests wait on it).
    int renderCount() const { return m_renderCount; }

signals:
    /// A left click (press and release within a few pixels, no drag) picked `result`.
    void picked(const hs::widgets::PickResult& result);

protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;

    void mousePressEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void enterEvent(QEnterEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    // VTK -> Qt: observers on the render window and the interactor.
    void onMakeCurrent(vtkObject* caller, unsigned long eventId, void* callData);
    void onIsCurrent(vtkObject* caller, unsigned long eventId, void* callData);
    void onFrame(vtkObject* caller, unsigned long eventId, void* callData);
    void onRenderRequest(vtkObject* caller, unsigned long eventId, void* callData);
    void onCreateTimer(vtkObject* caller, unsigned long eventId, void* callData);
    void onDestroyTimer(vtkObject* caller, unsigned long eventId, void* callData);
    void onCursorChanged(vtkObject* caller, unsigned long eventId, void* callData);

    void releaseGraphics();
    bool isOwnContextCurrent() const;
    QPoint toDevicePixels(const QPointF& pos) const;
    void setEventPosition(const QPointF& pos, Qt::KeyboardModifiers modifiers, int repeatCount = 0);
    void forwardMouseButton(QMouseEvent* event, bool press, int repeatCount);
    void forwardKey(QKeyEvent* event, bool press);

    vtkSmartPointer<vtkGenericOpenGLRenderWindow> m_renderWindow;
    vtkSmartPointer<vtkGenericRenderWindowInteractor> m_interactor;
    vtkSmartPointer<vtkRenderer> m_renderer;
    vtkSmartPointer<vtkCellPicker> m_picker;

    QSurface* m_surface = nullptr; ///< QOpenGLWidget's offscreen surface, known from initializeGL on
    bool m_needRender = true;      ///< false: paintGL only blits VTK's last frame
    bool m_inPaint = false;
    int m_renderCount = 0;
    int m_wheelAccumulator = 0;
    QPoint m_pressPos;
    bool m_clickCandidate = false;
    std::map<int, QTimer*> m_timers; ///< interactor timers by platform id
};

} // namespace hs::widgets

Q_DECLARE_METATYPE(hs::widgets::PickResult)
