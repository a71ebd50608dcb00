// Gyre in German and Chinese: the compiled translations reach the main window's menus and the undo
// steps' names, the Linguist sources stay complete as the code changes, the Preferences dialog
// stores the language, and a language Gyre does not know leaves it in English.

#include "app/language.h"
#include "app/main_window.h"
#include "app/preferences_dialog.h"
#include "gui_test_support.h"
#include "model/commands/set_keyframe_position_command.h"

#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFile>
#include <QMenu>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QTest>
#include <QTranslator>
#include <QXmlStreamReader>

using namespace gyre;

namespace {

// What a .ts file says of one message.
struct TsMessage {
    QString context;
    QString source;
    QString translationType; // "unfinished", "vanished", "obsolete", or empty when translated
    QStringList translations; // the translation, or each plural form of it
};

// Every message of the Linguist source at `path`.
QList<TsMessage> readTsFile(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("Cannot open %s", qPrintable(path));
    QXmlStreamReader xml(&file);
    QList<TsMessage> messages;
    QString context;
    bool plural = false;
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        const QStringView element = xml.name();
        if (element == u"name") {
            context = xml.readElementText();
        } else if (element == u"message") {
            plural = xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
            messages.append({context, {}, {}, {}});
        } else if (element == u"source") {
            messages.last().source = xml.readElementText();
        } else if (element == u"translation") {
            messages.last().translationType = xml.attributes().value(QLatin1String("type")).toString();
            if (!plural) // a plural's forms are its children
                messages.last().translations.append(xml.readElementText());
        } else if (element == u"numerusform") {
            messages.last().translations.append(xml.readElementText());
        }
    }
    if (xml.hasError())
        qFatal("%s: %s", qPrintable(path), qPrintable(xml.errorString()));
    return messages;
}

// The placeholders of a text (%1, %2, ..., %n, and QProgressBar's %v and %m), sorted.
QStringList placeholders(const QString& text)
{
    static const QRegularExpression placeholder(QStringLiteral("%(\\d+|n|v|m)"));
    QStringList found;
    for (const QRegularExpressionMatch& match : placeholder.globalMatch(text))
        found.append(match.captured());
    found.sort();
    return found;
}

// Whether `text` holds a keyboard accelerator: an & not doubled.
bool hasAccelerator(const QString& text)
{
    return text.contains(QRegularExpression(QStringLiteral("&(?!&)\\S")));
}

QString tsPath(const QString& language)
{
    return QStringLiteral(GYRE_TRANSLATIONS_DIR "/gyre_%1.ts").arg(language);
}

QMenu* menu(const app::MainWindow& window, const char* name)
{
    auto* found = window.findChild<QMenu*>(QLatin1String(name));
    if (found == nullptr)
        qFatal("No menu %s", name);
    return found;
}

QComboBox* languageBox(const app::PreferencesDialog& dialog)
{
    auto* box = dialog.findChild<QComboBox*>(QStringLiteral("languageBox"));
    if (box == nullptr)
        qFatal("No language box");
    return box;
}

// Chooses the entry `text` in the dialog's language box and presses OK.
void chooseLanguageAndAccept(app::PreferencesDialog& dialog, const QString& text)
{
    QComboBox* box = languageBox(dialog);
    const int index = box->findText(text);
    QVERIFY2(index >= 0, qPrintable(text));
    box->setCurrentIndex(index);
    auto* buttons = dialog.findChild<QDialogButtonBox*>(QStringLiteral("buttonBox"));
    QVERIFY(buttons != nullptr);
    QTest::mouseClick(buttons->button(QDialogButtonBox::Ok), Qt::LeftButton);
}

} // namespace

class TranslationsTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }
    void init() { QSettings().clear(); }

    void mainWindowSpeaksTheLanguage_data();
    void mainWindowSpeaksTheLanguage();
    void tsFilesAreComplete_data();
    void tsFilesAreComplete();
    void unknownLanguageLeavesGyreInEnglish();
    void preferencesStoreTheChosenLanguage();
    void preferencesStoreNoLanguageForSystemDefault();
    void preferencesCancelStoresNothing();
};

void TranslationsTest::mainWindowSpeaksTheLanguage_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("German") << QStringLiteral("de");
    QTest::newRow("Simplified Chinese") << QStringLiteral("zh_CN");
}

void TranslationsTest::mainWindowSpeaksTheLanguage()
{
    QFETCH(QString, language);
    // The embedded .qm read on its own, as the expectation.
    QTranslator expected;
    QVERIFY(expected.load(QStringLiteral(":/i18n/gyre_%1.qm").arg(language)));
    const QString file = expected.translate("MainWindow", "&File");
    const QString edit = expected.translate("MainWindow", "&Edit");
    const QString undo = expected.translate("gyre::app::MainWindow", "&Undo");
    const QString moveKey = expected.translate("gyre::model::Command", "Move Keyframe Position");
    for (const QString& text : {file, edit, undo, moveKey})
        QVERIFY2(!text.isEmpty(), qPrintable(language));
    QVERIFY(file != QLatin1String("&File"));

    const app::Translations translations(language);
    QVERIFY(translations.warning().isEmpty());
    app::MainWindow window;
    window.show();
    window.openBundledSample();
    QCOMPARE(menu(window, "menuFile")->title(), file);
    QCOMPARE(menu(window, "menuEdit")->title(), edit);
    // An undo step made in the model is named in the language too, under the app's Undo prefix.
    const model::SceneObject& object = window.document().scene().objects.front();
    const Eigen::Vector3d moved = object.track.keys.front().pose.position + Eigen::Vector3d::UnitX();
    window.document().undoStack().push(new model::SetKeyframePositionCommand(window.document(), object.id, 0, moved));
    auto* undoAction = window.findChild<QAction*>(QStringLiteral("actionUndo"));
    QVERIFY(undoAction != nullptr);
    QCOMPARE(undoAction->text(), undo + QLatin1Char(' ') + moveKey);
}

void TranslationsTest::tsFilesAreComplete_data()
{
    QTest::addColumn<QString>("path");
    QTest::newRow("German") << tsPath(QStringLiteral("de"));
    QTest::newRow("Simplified Chinese") << tsPath(QStringLiteral("zh_CN"));
}

void TranslationsTest::tsFilesAreComplete()
{
    QFETCH(QString, path);
    const QList<TsMessage> messages = readTsFile(path);
    QVERIFY(messages.size() > 300);
    for (const TsMessage& message : messages) {
        const QString where = message.context + QLatin1String(": ") + message.source;
        QVERIFY2(message.translationType.isEmpty(),
                 qPrintable(where + QLatin1String(" is ") + message.translationType));
        QVERIFY2(!message.translations.isEmpty(), qPrintable(where));
        for (const QString& translation : message.translations) {
            QVERIFY2(!translation.isEmpty(), qPrintable(where));
            // A plural form may leave out %n only where the language has one form for one item; none does.
            QVERIFY2(placeholders(translation) == placeholders(message.source),
                     qPrintable(where + QLatin1String(" -> ") + translation));
            QVERIFY2(hasAccelerator(translation) == hasAccelerator(message.source),
                     qPrintable(where + QLatin1String(" -> ") + translation));
        }
    }
}

void TranslationsTest::unknownLanguageLeavesGyreInEnglish()
{
    const app::Translations translations(QStringLiteral("xx"));
    QVERIFY(translations.warning().contains(QLatin1String("\"xx\"")));
    QCOMPARE(QCoreApplication::translate("MainWindow", "&File"), QStringLiteral("&File"));
    QVERIFY(!app::localeForLanguage(QStringLiteral("xx")).has_value());
    QCOMPARE(app::localeForLanguage(QString()), QLocale::system());
}

void TranslationsTest::preferencesStoreTheChosenLanguage()
{
    app::PreferencesDialog dialog;
    dialog.show();
    QCOMPARE(languageBox(dialog)->currentIndex(), 0); // System default, as nothing is stored
    chooseLanguageAndAccept(dialog, QStringLiteral("Deutsch"));
    QCOMPARE(dialog.result(), int(QDialog::Accepted));
    QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), QStringLiteral("de"));
    QCOMPARE(app::languageSetting(), QStringLiteral("de"));

    app::PreferencesDialog reopened;
    QCOMPARE(languageBox(reopened)->currentText(), QStringLiteral("Deutsch"));
}

void TranslationsTest::preferencesStoreNoLanguageForSystemDefault()
{
    app::setLanguageSetting(QStringLiteral("zh_CN"));
    app::PreferencesDialog dialog;
    dialog.show();
    QCOMPARE(languageBox(dialog)->currentText(), QStringLiteral("简体中文"));
    chooseLanguageAndAccept(dialog, QStringLiteral("System default"));
    QVERIFY(!QSettings().contains(QStringLiteral("language")));
    QVERIFY(app::languageSetting().isEmpty());
}

void TranslationsTest::preferencesCancelStoresNothing()
{
    app::PreferencesDialog dialog;
    dialog.show();
    languageBox(dialog)->setCurrentIndex(languageBox(dialog)->findText(QStringLiteral("English")));
    auto* buttons = dialog.findChild<QDialogButtonBox*>(QStringLiteral("buttonBox"));
    QVERIFY(buttons != nullptr);
    QTest::mouseClick(buttons->button(QDialogButtonBox::Cancel), Qt::LeftButton);
    QCOMPARE(dialog.result(), int(QDialog::Rejected));
    QVERIFY(!QSettings().contains(QStringLiteral("language")));
}

QTEST_MAIN(TranslationsTest)
#include "tst_translations.moc"
