// gyre, the desktop application: opens the file named on the command line, or the bundled sample.

#include "app/app_icon.h"
#include "app/language.h"
#include "app/main_window.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTimer>

#include <cstdio>
#include <memory>

namespace {

// Saves a picture of the window to `path` after `delayMilliseconds` and quits, with status 1 if the
// picture cannot be written: screenshots for the documentation, and a check that the window draws.
void screenshotAndQuit(QWidget& window, const QString& path, int delayMilliseconds)
{
    QTimer::singleShot(delayMilliseconds, &window, [&window, path] {
        if (window.grab().save(path)) {
            QApplication::exit(0);
            return;
        }
        std::fprintf(stderr, "gyre: %s\n",
                     qPrintable(QApplication::translate("main", "%1: cannot write the screenshot").arg(path)));
        QApplication::exit(1);
    });
}

// Exit status 2, as for gyre-cli: the command line was wrong.
int commandLineError(const QString& message)
{
    std::fprintf(stderr, "gyre: %s\n", qPrintable(message));
    return 2;
}

} // namespace

int main(int argc, char* argv[])
{
    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Gyre"));
    QApplication::setApplicationName(QStringLiteral("Gyre"));
    QApplication::setApplicationVersion(QStringLiteral(GYRE_VERSION));
    QApplication::setWindowIcon(gyre::app::appIcon());
    // Wayland compositors find the window's icon and name through the installed desktop entry.
    QGuiApplication::setDesktopFileName(QStringLiteral(GYRE_APP_ID));
    // The language chosen in the preferences, so that even --help speaks it; --language may replace it.
    auto translations = std::make_unique<gyre::app::Translations>(gyre::app::languageSetting());

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "Edit the rotations of animated rigid objects."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QStringLiteral("file"),
        QApplication::translate("main", "A Gyre project to open, or a scene file (FBX, glTF, ...) to import."));
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QApplication::translate("main", "Save a picture of the window to <file> after a few seconds, then quit."),
        QStringLiteral("file"));
    const QCommandLineOption delay(QStringLiteral("delay"),
                                   QApplication::translate("main", "Wait <ms> milliseconds before the screenshot."),
                                   QStringLiteral("ms"), QStringLiteral("3000"));
    const QCommandLineOption language(
        QStringLiteral("language"),
        QApplication::translate("main", "Speak <language> (%1) instead of the one chosen in the preferences.")
            .arg(gyre::app::languageCodes().join(QStringLiteral(", "))),
        QStringLiteral("language"));
    parser.addOptions({screenshot, delay, language});
    parser.process(application);
    bool delayIsNumber = false;
    const int delayMilliseconds = parser.value(delay).toInt(&delayIsNumber);
    if (!delayIsNumber || delayMilliseconds < 0)
        return commandLineError(QApplication::translate("main", "--delay takes a number of milliseconds, not \"%1\".")
                                    .arg(parser.value(delay)));
    if (parser.positionalArguments().size() > 1)
        return commandLineError(QApplication::translate("main", "give at most one file to open."));
    if (parser.isSet(language)) {
        translations.reset(); // its translators leave before the new ones come
        translations = std::make_unique<gyre::app::Translations>(parser.value(language));
    }
    if (!translations->warning().isEmpty())
        std::fprintf(stderr, "gyre: %s\n", qPrintable(translations->warning()));

    gyre::app::MainWindow window;
    window.show();
    const bool recovered = window.recoverAndStartAutosave();
    const QStringList files = parser.positionalArguments();
    if (!files.isEmpty())
        window.openFile(files.front());
    else if (!recovered)
        window.openBundledSample();
    if (parser.isSet(screenshot))
        screenshotAndQuit(window, parser.value(screenshot), delayMilliseconds);
    return QApplication::exec();
}
