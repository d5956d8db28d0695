// Qt Test for the Review panel: a package's pathologies and textures listed, Visit pointing the preview at a
// pathology, ratings written beside the package (whose checksums stay valid) and read back, the folder's summary.
#include "hs/generate/Generate.h"
#include "hs/scene/Review.h"
#include "hs/scene/ScenePackage.h"
#include "hs/widgets/panels/ReviewPanel.h"
#include "hs/widgets/view/HysteroscopicPreview.h"

#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using hs::widgets::ReviewPanel;

class TestReviewPanel : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void listsRatesSavesBesideThePackageAndReadsBack();
    void visitLooksAtThePathology();

private:
    QTemporaryDir m_dir;
    QString m_package;
    std::shared_ptr<const hs::scene::Scene> m_scene;
    QString m_identity;
};

void TestReviewPanel::initTestCase() {
    hs::scene::CaseSpec spec = hs::scene::defaultCase();
    spec.meshing.targetVertices = 4000;
    spec.texture.sizePx = 256;
    auto generated = hs::generate::generateScene(spec);
    QVERIFY2(generated.ok(), generated.ok() ? "" : generated.error().message().c_str());
    m_package = m_dir.filePath("scene");
    const std::string path = QFile::encodeName(m_package).toStdString();
    QVERIFY(hs::scene::writeScenePackage(*generated->scene, path).ok());
    auto read = hs::scene::readScenePackage(path);
    QVERIFY(read.ok());
    m_scene = std::make_shared<const hs::scene::Scene>(std::move(read).value());
    m_identity = QString::fromStdString(*hs::scene::packageIdentity(path));
}

void TestReviewPanel::listsRatesSavesBesideThePackageAndReadsBack() {
    ReviewPanel panel;
    QVERIFY(!panel.isEnabled());
    panel.open(m_scene, m_package, m_identity);
    QVERIFY(panel.isEnabled());
    auto* pathologies = panel.findChild<QTableWidget*>("reviewPathologyTable");
    QCOMPARE(pathologies->rowCount(), int(m_scene->caseSpec.pathologies.size()));
    QCOMPARE(pathologies->item(0, 0)->text(), QString::fromStdString(m_scene->caseSpec.pathologies[0].id));

    panel.findChild<QSpinBox*>("pathologyScore0")->setValue(4);
    auto* comment = panel.findChild<QLineEdit*>("pathologyComment0");
    QTest::keyClicks(comment, "too smooth");
    panel.findChild<QSpinBox*>("textureScore0")->setValue(3);
    QVERIFY(panel.isModified());
    panel.findChild<QPushButton*>("saveReviewButton")->click();
    QVERIFY(!panel.isModified());

    const std::string reviewPath = hs::scene::reviewPathFor(QFile::encodeName(m_package).toStdString());
    auto saved = hs::scene::loadReview(reviewPath);
    QVERIFY(saved.ok());
    QCOMPARE(*saved->pathologies[0].rating.score, 4);
    QCOMPARE(saved->pathologies[0].rating.comment, std::string("too smooth"));
    // Beside the package, never inside it: the package still verifies.
    QVERIFY(hs::scene::verifyScenePackage(QFile::encodeName(m_package).toStdString()).ok());
    QVERIFY(panel.findChild<QTableWidget*>("reviewSummaryTable")->rowCount() >= 2);

    ReviewPanel again; // a later session reads the ratings back
    again.open(m_scene, m_package, m_identity);
    QCOMPARE(again.findChild<QSpinBox*>("pathologyScore0")->value(), 4);
    QCOMPARE(again.findChild<QLineEdit*>("pathologyComment0")->text(), QString("too smooth"));
}

void TestReviewPanel::visitLooksAtThePathology() {
    ReviewPanel panel;
    panel.open(m_scene, m_package, m_identity);
    QVERIFY(!panel.visitPathology(0)); // no preview to point
    hs::widgets::HysteroscopicPreview preview;
    preview.resize(300, 400);
    preview.show();
    preview.setScene(m_scene);
    QVERIFY(preview.hasScene());
    panel.setPreview(&preview);
    const QImage before = preview.grabImage();
    QVERIFY(panel.visitPathology(0));
    const QImage after = preview.grabImage();
    QVERIFY(before != after);
}

QTEST_MAIN(TestReviewPanel)
#include "TestReviewPanel.moc"
