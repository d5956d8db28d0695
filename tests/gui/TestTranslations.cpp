// Qt Test for the embedded translations and the translator's English fallback.
#include "hs/translations/Translations.h"

#include <QCoreApplication>
#include <QFile>
#include <QLocale>
#include <QTest>
#include <QTranslator>

class TestTranslations : public QObject {
    Q_OBJECT

private slots:
    void cleanup();
    void everyLanguageIsEmbedded();
    void loadsRequestedLanguage_data();
    void loadsRequestedLanguage();
    void unknownLanguageFallsBackToEnglish();
    void everyStringIsTranslated_data();
    void everyStringIsTranslated();

private:
    static QString fileMenuTitle() { return QCoreApplication::translate("hs::workstation::MainWindow", "&File"); }
    void removeTranslators();
};

void TestTranslations::removeTranslators() {
    const auto translators = QCoreApplication::instance()->findChildren<QTranslator*>();
    for (QTranslator* translator : translators) {
        QCoreApplication::removeTranslator(translator);
        delete translator;
    }
}

void TestTranslations::cleanup() {
    removeTranslators();
    QLocale::setDefault(QLocale::c());
}

void TestTranslations::everyLanguageIsEmbedded() {
    const QStringList languages = hs::translations::availableLanguages();
    QCOMPARE(languages, (QStringList{"de", "fr", "it"}));
}

void TestTranslations::loadsRequestedLanguage_data() {
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("fileMenu");
    QTest::newRow("German") << "de"
                            << "&Datei";
    QTest::newRow("French") << "fr"
                            << "&Fichier";
    QTest::newRow("Italian") << "it"
                             << "&File";
    QTest::newRow("Swiss German") << "de_CH"
                                  << "&Datei";
    QTest::newRow("English") << "en"
                             << "&File";
}

void TestTranslations::loadsRequestedLanguage() {
    QFETCH(QString, language);
    QFETCH(QString, fileMenu);
    const QString loaded = hs::translations::installTranslators(*QCoreApplication::instance(), language);
    QCOMPARE(loaded, language.left(2));
    QCOMPARE(fileMenuTitle(), fileMenu);
    const QString title = QCoreApplication::translate("hs::workstation::MainWindow", "Open Mesh");
    QCOMPARE(title == QStringLiteral("Open Mesh"), language == QStringLiteral("en"));
    // The simulator's window shares the files.
    const QString simulator = QCoreApplication::translate("hs::simapp::SimWindow", "hysteroscene simulator");
    QCOMPARE(simulator == QStringLiteral("hysteroscene simulator"), language == QStringLiteral("en"));
}

void TestTranslations::unknownLanguageFallsBackToEnglish() {
    QCOMPARE(hs::translations::installTranslators(*QCoreApplication::instance(), "tlh"), QStringLiteral("en"));
    QCOMPARE(fileMenuTitle(), QStringLiteral("&File"));
}

void TestTranslations::everyStringIsTranslated_data() {
    QTest::addColumn<QString>("language");
    for (const char* language : {"de", "fr", "it"})
        QTest::newRow(language) << language;
}

void TestTranslations::everyStringIsTranslated() {
    // The .ts files in the source tree: an entry lupdate added and nobody translated is marked unfinished.
    QFETCH(QString, language);
    QFile ts(QStringLiteral(HS_TRANSLATIONS_DIR "/hysteroscene_%1.ts").arg(language));
    QVERIFY(ts.open(QIODevice::ReadOnly));
    const QByteArray text = ts.readAll();
    QVERIFY(text.count("<message") > 400);
    QCOMPARE(text.count("type=\"unfinished\""), 0);
}

QTEST_GUILESS_MAIN(TestTranslations)
#include "TestTranslations.moc"
