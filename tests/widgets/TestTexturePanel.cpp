// Qt Test for the Texture panel: exemplar images refused when they are no image, too small or too large, and taken
// when the texture stage can read them; Texture bakes the maps, which the 2-D view shows and zooms.
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/TexturePanel.h"

#include <QComboBox>
#include <QFile>
#include <QGraphicsPixmapItem>
#include <QGraphicsView>
#include <QImage>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

using hs::widgets::CaseDocument;
using hs::widgets::GenerationSession;
using hs::widgets::TexturePanel;

class TestTexturePanel : public QObject {
    Q_OBJECT

private slots:
    void refusesWhatIsNoExemplarAndTakesAnImage();
    void texturesAndShowsTheMaps();
};

void TestTexturePanel::refusesWhatIsNoExemplarAndTakesAnImage() {
    QTemporaryDir dir;
    CaseDocument document;
    GenerationSession session(document);
    session.setAutoUpdate(false);
    TexturePanel panel(document, session);
    auto* message = panel.findChild<QLabel*>("textureMessageLabel");

    QFile text(dir.filePath("notes.png"));
    QVERIFY(text.open(QIODevice::WriteOnly));
    text.write("this is not an image\n");
    text.close();
    QVERIFY(!panel.setExemplar(0, text.fileName()));
    QVERIFY2(message->text().contains("notes.png"), qPrintable(message->text()));
    QVERIFY(!document.spec().texture.exemplars.endometrium.has_value());

    QImage tiny(8, 8, QImage::Format_RGB888);
    tiny.fill(Qt::red);
    QVERIFY(tiny.save(dir.filePath("tiny.png")));
    QVERIFY(!panel.setExemplar(0, dir.filePath("tiny.png")));
    QVERIFY2(message->text().contains("16"), qPrintable(message->text()));

    QImage big(5000, 20, QImage::Format_RGB888);
    big.fill(Qt::blue);
    QVERIFY(big.save(dir.filePath("big.png")));
    QVERIFY(!panel.setExemplar(1, dir.filePath("big.png")));
    QVERIFY(!document.spec().texture.exemplars.myoma.has_value());

    QImage good(64, 64, QImage::Format_RGB888);
    good.fill(QColor(200, 120, 120));
    QVERIFY(good.save(dir.filePath("good.png")));
    QVERIFY(panel.setExemplar(2, dir.filePath("good.png")));
    QCOMPARE(QString::fromStdString(*document.spec().texture.exemplars.polyp), dir.filePath("good.png"));
    QCOMPARE(panel.findChild<QLabel*>("exemplarLabel2")->text(), QString("good.png"));
    document.undoStack()->undo();
    QCOMPARE(panel.findChild<QLabel*>("exemplarLabel2")->text(), QString("Bundled"));

    // The cervical canal has an exemplar row of its own (the case's texture.exemplars.cervicalCanal).
    QVERIFY(panel.setExemplar(3, dir.filePath("good.png")));
    QCOMPARE(QString::fromStdString(*document.spec().texture.exemplars.cervicalCanal), dir.filePath("good.png"));
    QVERIFY(!document.spec().texture.exemplars.polyp.has_value());
    QCOMPARE(panel.findChild<QLabel*>("exemplarLabel3")->text(), QString("good.png"));
    panel.findChild<QToolButton*>("exemplarBundledButton3")->click();
    QVERIFY(!document.spec().texture.exemplars.cervicalCanal.has_value());
    QCOMPARE(panel.findChild<QLabel*>("exemplarLabel3")->text(), QString("Bundled"));
}

void TestTexturePanel::texturesAndShowsTheMaps() {
    CaseDocument document;
    document.edit("light", [](hs::scene::CaseSpec& s) {
        s.meshing.targetVertices = 4000; // a small mesh and small maps keep the test short
        s.texture.sizePx = 256;
    });
    GenerationSession session(document);
    session.setAutoUpdate(false);
    TexturePanel panel(document, session);
    panel.show();
    QSignalSpy changed(&session, &GenerationSession::resultsChanged);
    panel.findChild<QPushButton*>("textureButton")->click();
    QVERIFY(changed.wait(180000));
    QVERIFY(session.isCurrent(hs::generate::Stage::Texture));
    auto* view = panel.findChild<QGraphicsView*>("mapView");
    QCOMPARE(view->scene()->sceneRect().width(), 256.0);
    panel.findChild<QComboBox*>("mapCombo")->setCurrentIndex(2); // roughness
    QCOMPARE(view->scene()->sceneRect().width(), 256.0);
    panel.setZoom(4.0);
    QCOMPARE(view->transform().m11(), 4.0);
}

QTEST_MAIN(TestTexturePanel)
#include "TestTexturePanel.moc"
