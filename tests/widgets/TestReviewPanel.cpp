// Qt Test for the Review panel: a package's pathologies and textures listed, Visit pointing the preview at a
// pathology, ratings written beside the package (whose checksums stay valid) and read back, the folder's summary.
#include "hs/generate/Generate.h"
#include "hs/scene/Review.h"
#include "hs/scene/ScenePackage.h"
#include "hs/widgets/panels/ReviewPanel.h"
#include "hs/widgets/view/HysteroscopicPreview.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
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
    void refusesTheReviewOfAnotherPackageByNameAndKeepsIt();

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

void TestReviewPanel::refusesTheReviewOfAnotherPackageByNameAndKeepsIt() {
    QTemporaryDir dir;
    const QString package = dir.filePath("other");
    QVERIFY(QDir().mkpath(package));
    const std::string reviewPath = hs::scene::reviewPathFor(QFile::encodeName(package).toStdString());
    // A review of another package (another manifest checksum) stands where this package's review goes.
    hs::scene::Review foreign = hs::scene::emptyReview(*m_scene, std::string(64, 'a'));
    foreign.reviewer = "someone else";
    foreign.pathologies[0].rating.score = 2;
    QVERIFY(hs::scene::saveReview(foreign, reviewPath).ok());

    ReviewPanel panel;
    panel.open(m_scene, package, m_identity);
    const QString message = panel.findChild<QLabel*>("reviewMessageLabel")->text();
    QVERIFY2(message.contains(QFileInfo(QString::fromStdString(reviewPath)).fileName()) &&
                 message.contains("another package") && message.contains("aaaaaaaaaaaa"),
             qPrintable(message));
    QCOMPARE(panel.findChild<QSpinBox*>("pathologyScore0")->value(), 0); // not loaded
    QVERIFY(panel.findChild<QLineEdit*>("reviewerEdit")->text().isEmpty());

    // Saving writes this package's review and keeps the other one beside it, unchanged.
    panel.findChild<QSpinBox*>("pathologyScore0")->setValue(5);
    QVERIFY(panel.save());
    auto mine = hs::scene::loadReview(reviewPath);
    QVERIFY(mine.ok());
    QCOMPARE(QString::fromStdString(mine->packageSha256), m_identity);
    auto kept = hs::scene::loadReview(reviewPath + ".other-1");
    QVERIFY(kept.ok());
    QCOMPARE(kept->reviewer, std::string("someone else"));
    QCOMPARE(*kept->pathologies[0].rating.score, 2);
}

QTEST_MAIN(TestReviewPanel)
#include "TestReviewPanel.moc"
