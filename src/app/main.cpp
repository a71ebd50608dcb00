// gyre, the desktop application: opens the files named on the command line, or the bundled sample.

#include "app/main_window.h"

#include <QApplication>
#include <QCommandLineParser>

int main(int argc, char* argv[])
{
    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Gyre"));
    QApplication::setApplicationName(QStringLiteral("Gyre"));
    QApplication::setApplicationVersion(QStringLiteral(GYRE_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "Edit the rotations of animated rigid objects."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("file"),
                                 QApplication::translate("main", "A Gyre project to open."));
    parser.process(application);

    gyre::app::MainWindow window;
    window.show();
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty())
        window.openBundledSample();
    else
        window.openProject(files.front());
    return QApplication::exec();
}
