#include "hs/widgets/panels/TexturePanel.h"

#include "hs/texture/Bake.h"
#include "hs/texture/Synthesis.h"
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/CaseEdits.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QGraphicsPixmapItem>
#include <QGraphicsScene>
#include <QGraphicsView>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

namespace hs::widgets {

namespace {

using scene::CaseSpec;

constexpr int kVesselKey = 501;

std::optional<std::string> scene::TextureExemplars::*exemplarOf(int index) {
    switch (index) {
    case 0:
        return &scene::TextureExemplars::endometrium;
    case 1:
        return &scene::TextureExemplars::myoma;
    case 2:
        return &scene::TextureExemplars::polyp;
    default:
        return &scene::TextureExemplars::cervicalCanal;
    }
}

QString exemplarName(int index) {
    switch (index) {
    case 0:
        return TexturePanel::tr("Endometrium");
    case 1:
        return TexturePanel::tr("Myoma");
    case 2:
        return TexturePanel::tr("Polyp");
    default:
        return TexturePanel::tr("Cervical canal");
    }
}

/// An 8-bit map as a QImage (1 channel: grey; 3: RGB), copied.
QImage toQImage(const ImageU8& map) {
    if (map.empty())
        return {};
    const QImage::Format format = map.channels() == 1 ? QImage::Format_Grayscale8 : QImage::Format_RGB888;
    QImage image(map.width(), map.height(), format);
    for (int y = 0; y < map.height(); ++y) {
        uchar* line = image.scanLine(y);
        for (int x = 0; x < map.width(); ++x)
            for (int c = 0; c < std::min(map.channels(), 3); ++c)
                line[x * std::min(map.channels(), 3) + c] = map.at(x, y, c);
    }
    return image;
}

} // namespace

TexturePanel::TexturePanel(CaseDocument& document, GenerationSession& session, QWidget* parent)
    : QWidget(parent), m_document(document), m_session(session) {
    setObjectName("texturePanel");
    auto* layout = new QVBoxLayout(this);
    auto* group = new QGroupBox(tr("Texture"), this);
    auto* form = new QFormLayout(group);
    m_sizeCombo = new QComboBox(group);
    m_sizeCombo->setObjectName("textureSizeCombo");
    for (int size : {256, 512, 1024, 2048, 4096})
        m_sizeCombo->addItem(tr("%1 × %1 px").arg(size), size);
    m_sizeCombo->setToolTip(tr("Side of each square map in pixels"));
    form->addRow(tr("Map &size"), m_sizeCombo);
    m_vesselSpin = new QDoubleSpinBox(group);
    m_vesselSpin->setObjectName("vesselSpin");
    m_vesselSpin->setRange(0.0, 20.0);
    m_vesselSpin->setSingleStep(0.1);
    m_vesselSpin->setDecimals(2);
    m_vesselSpin->setKeyboardTracking(false);
    m_vesselSpin->setToolTip(tr("Vessels relative to the default network, %1; 0: none")
                                 .arg(rangeText(scene::limits::kVesselDensity, {}, 1)));
    form->addRow(tr("&Vessel density"), m_vesselSpin);
    for (int i = 0; i < kExemplarCount; ++i) {
        auto* row = new QHBoxLayout;
        m_exemplarLabels[static_cast<std::size_t>(i)] = new QLabel(group);
        m_exemplarLabels[static_cast<std::size_t>(i)]->setObjectName(QStringLiteral("exemplarLabel%1").arg(i));
        auto* choose = new QToolButton(group);
        choose->setObjectName(QStringLiteral("exemplarChooseButton%1").arg(i));
        choose->setText(tr("Choose..."));
        choose->setToolTip(tr("Use your own image (PNG, JPEG, EXR, TIFF; %1 – %2 px a side): a crop of a real "
                              "hysteroscopic view")
                               .arg(texture::SynthesisParams::kMinExemplarSide)
                               .arg(texture::SynthesisParams::kMaxExemplarSide));
        auto* bundled = new QToolButton(group);
        bundled->setObjectName(QStringLiteral("exemplarBundledButton%1").arg(i));
        bundled->setText(tr("Bundled"));
        bundled->setToolTip(tr("Use the bundled procedural exemplar"));
        row->addWidget(m_exemplarLabels[static_cast<std::size_t>(i)], 1);
        row->addWidget(choose);
        row->addWidget(bundled);
        form->addRow(exemplarName(i), row);
        connect(choose, &QToolButton::clicked, this, [this, i] { emit exemplarBrowseRequested(i); });
        connect(bundled, &QToolButton::clicked, this, [this, i] {
            const auto member = exemplarOf(i);
            m_document.edit(tr("Bundled exemplar"), [member](CaseSpec& s) { (s.texture.exemplars.*member).reset(); });
        });
    }
    m_textureButton = new QPushButton(tr("&Texture"), group);
    m_textureButton->setObjectName("textureButton");
    m_textureButton->setToolTip(tr("Synthesize and bake the maps on the final surface (Ctrl+T)"));
    form->addRow(m_textureButton);
    m_messageLabel = new QLabel(group);
    m_messageLabel->setObjectName("textureMessageLabel");
    m_messageLabel->setWordWrap(true);
    m_messageLabel->setStyleSheet(QStringLiteral("color: #c0392b;"));
    m_messageLabel->setVisible(false);
    form->addRow(m_messageLabel);
    layout->addWidget(group);

    auto* maps = new QGroupBox(tr("Maps"), this);
    auto* mapBox = new QVBoxLayout(maps);
    auto* mapRow = new QHBoxLayout;
    m_mapCombo = new QComboBox(maps);
    m_mapCombo->setObjectName("mapCombo");
    m_mapCombo->addItems({tr("Albedo"), tr("Normal"), tr("Roughness")});
    auto* zoomIn = new QToolButton(maps);
    zoomIn->setObjectName("zoomInButton");
    zoomIn->setText(QStringLiteral("+"));
    zoomIn->setToolTip(tr("Zoom in"));
    auto* zoomOut = new QToolButton(maps);
    zoomOut->setObjectName("zoomOutButton");
    zoomOut->setText(QStringLiteral("−"));
    zoomOut->setToolTip(tr("Zoom out"));
    auto* fit = new QToolButton(maps);
    fit->setObjectName("zoomFitButton");
    fit->setText(tr("Fit"));
    mapRow->addWidget(m_mapCombo, 1);
    mapRow->addWidget(zoomOut);
    mapRow->addWidget(zoomIn);
    mapRow->addWidget(fit);
    mapBox->addLayout(mapRow);
    m_mapView = new QGraphicsView(maps);
    m_mapView->setObjectName("mapView");
    m_mapView->setScene(new QGraphicsScene(m_mapView));
    m_mapView->setDragMode(QGraphicsView::ScrollHandDrag);
    m_mapView->setMinimumHeight(240);
    m_mapItem = m_mapView->scene()->addPixmap(QPixmap());
    m_mapItem->setTransformationMode(Qt::FastTransformation); // texels stay sharp when zoomed in
    mapBox->addWidget(m_mapView);
    layout->addWidget(maps);
    layout->addStretch(1);

    connect(zoomIn, &QToolButton::clicked, this, [this] { setZoom(m_zoom * 2.0); });
    connect(zoomOut, &QToolButton::clicked, this, [this] { setZoom(m_zoom / 2.0); });
    connect(fit, &QToolButton::clicked, this, [this] {
        m_mapView->fitInView(m_mapItem, Qt::KeepAspectRatio);
        m_zoom = m_mapView->transform().m11();
    });
    connect(m_mapCombo, &QComboBox::currentIndexChanged, this, &TexturePanel::showMap);
    connect(m_sizeCombo, &QComboBox::currentIndexChanged, this, [this](int index) {
        const int size = m_sizeCombo->itemData(index).toInt();
        if (!m_refreshing)
            tryEdit(
                m_document, tr("Map size"), [size](CaseSpec& s) { s.texture.sizePx = size; },
                QStringLiteral("/texture"), m_messageLabel, m_sizeCombo);
    });
    connect(m_vesselSpin, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!m_refreshing)
            tryEdit(
                m_document, tr("Vessel density"), [v](CaseSpec& s) { s.texture.vesselDensity = v; },
                QStringLiteral("/texture"), m_messageLabel, m_vesselSpin, kVesselKey);
    });
    // Through the scene's assembly (cheap): the hysteroscopic preview places the scope by the scene's labels.
    connect(m_textureButton, &QPushButton::clicked, this, [this] { m_session.runThrough(generate::Stage::Scene); });
    connect(&m_document, &CaseDocument::changed, this, &TexturePanel::refresh);
    connect(&m_session, &GenerationSession::resultsChanged, this, &TexturePanel::showMap);
    refresh();
}

bool TexturePanel::setExemplar(int index, const QString& path) {
    if (index < 0 || index >= kExemplarCount || path.isEmpty())
        return false;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    // Read it as the texture stage will: a file that is no image, or too small or large, is refused now.
    auto image = texture::readExemplarFile(QFile::encodeName(absolute).toStdString());
    if (!image) {
        QString why;
        switch (image.error().code) {
        case ErrorCode::NotFound:
            why = tr("The file %1 does not exist.");
            break;
        case ErrorCode::LimitExceeded:
        case ErrorCode::InvalidInput:
            why = tr("The image %1 is too small or too large: each side must be %2 – %3 px.");
            break;
        default:
            why = tr("The file %1 is not an image this program reads (PNG, JPEG, EXR, TIFF).");
            break;
        }
        why = why.arg(QFileInfo(path).fileName())
                  .arg(texture::SynthesisParams::kMinExemplarSide)
                  .arg(texture::SynthesisParams::kMaxExemplarSide);
        m_messageLabel->setText(why);
        m_messageLabel->setToolTip(QString::fromStdString(image.error().message()));
        m_messageLabel->setVisible(true);
        return false;
    }
    const auto member = exemplarOf(index);
    return tryEdit(
        m_document, tr("Exemplar image"),
        [member, file = QFile::encodeName(absolute).toStdString()](CaseSpec& s) { s.texture.exemplars.*member = file; },
        QStringLiteral("/texture"), m_messageLabel);
}

void TexturePanel::setZoom(double zoom) {
    m_zoom = std::clamp(zoom, 1.0 / 16.0, 32.0);
    m_mapView->setTransform(QTransform::fromScale(m_zoom, m_zoom));
}

void TexturePanel::refresh() {
    m_refreshing = true;
    const scene::TextureParams& t = m_document.spec().texture;
    const int sizeIndex = m_sizeCombo->findData(t.sizePx);
    if (sizeIndex < 0) // a size from a file that the list does not offer
        m_sizeCombo->addItem(tr("%1 × %1 px").arg(t.sizePx), t.sizePx);
    m_sizeCombo->setCurrentIndex(m_sizeCombo->findData(t.sizePx));
    if (!m_vesselSpin->property("invalid").toBool())
        m_vesselSpin->setValue(t.vesselDensity);
    for (int i = 0; i < kExemplarCount; ++i) {
        const std::optional<std::string>& file = t.exemplars.*exemplarOf(i);
        QLabel* label = m_exemplarLabels[static_cast<std::size_t>(i)];
        label->setText(file ? QFileInfo(QString::fromStdString(*file)).fileName() : tr("Bundled"));
        label->setToolTip(file ? QString::fromStdString(*file) : tr("The bundled procedural exemplar"));
    }
    m_refreshing = false;
}

void TexturePanel::showMap() {
    const auto results = m_session.results();
    if (!results || !results->appearance) {
        m_mapItem->setPixmap(QPixmap());
        return;
    }
    const scene::VisualSurface& v = results->appearance->surface;
    const ImageU8& map = m_mapCombo->currentIndex() == 0   ? v.albedo
                         : m_mapCombo->currentIndex() == 1 ? v.normal
                                                           : v.roughness;
    m_mapItem->setPixmap(QPixmap::fromImage(toQImage(map)));
    m_mapView->scene()->setSceneRect(m_mapItem->boundingRect());
}

} // namespace hs::widgets
