#pragma once
/// The Texture panel: the texture stage's parameters (map size, vessel density, the exemplar of each appearance:
/// the bundled procedural one or the user's own image, validated as the texture stage reads it), Texture to run the
/// stage in the background (the 3-D view then shows the textured surface), and each baked map (albedo, normal,
/// roughness) in a 2-D view with zoom.

#include <QWidget>

#include <array>

class QComboBox;
class QGraphicsPixmapItem;
class QGraphicsView;
class QLabel;
class QPushButton;
class QDoubleSpinBox;

namespace hs::widgets {

class CaseDocument;
class GenerationSession;

class TexturePanel : public QWidget {
    Q_OBJECT

public:
    TexturePanel(CaseDocument& document, GenerationSession& session, QWidget* parent = nullptr);

    /// Appearance classes with an exemplar, in the case's order: endometrium, myoma, polyp.
    static constexpr int kExemplarCount = 4;
    /// Takes `path` as the exemplar of class `index` when it is an image the texture stage accepts; otherwise says
    /// why (not an image, too small, too large) and leaves the case as it was. Returns whether it was taken.
    bool setExemplar(int index, const QString& path);
    /// The map view's zoom factor (1: one texel per pixel).
    double zoom() const { return m_zoom; }
    void setZoom(double zoom);

signals:
    /// "Choose..." was clicked for exemplar `index`: the window asks for an image and calls setExemplar().
    void exemplarBrowseRequested(int index);

private:
    void refresh();
    void showMap();

    CaseDocument& m_document;
    GenerationSession& m_session;
    bool m_refreshing = false;
    double m_zoom = 1.0;

    QComboBox* m_sizeCombo = nullptr;
    QDoubleSpinBox* m_vesselSpin = nullptr;
    std::array<QLabel*, kExemplarCount> m_exemplarLabels{};
    QPushButton* m_textureButton = nullptr;
    QLabel* m_messageLabel = nullptr;
    QComboBox* m_mapCombo = nullptr;
    QGraphicsView* m_mapView = nullptr;
    QGraphicsPixmapItem* m_mapItem = nullptr;
};

} // namespace hs::widgets
