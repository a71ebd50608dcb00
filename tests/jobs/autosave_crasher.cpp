// A session that crashes: it ends at once, with no destructors run, as a crash would. tst_autosave
// starts it to leave a crashed session's files behind.
// Usage:
//   autosave_crasher DIRECTORY DOCUMENT_PATH   edits a document, crashes after its first autosave
//   autosave_crasher --recover DIRECTORY       recovers the newest copy there, crashes before any edit
//   autosave_crasher --idle DIRECTORY          crashes before any edit, leaving its lock alone

#include "jobs/autosave.h"
#include "model/commands/import_objects_command.h"

#include <QCoreApplication>

#include <chrono>
#include <cstdlib>

using namespace gyre::jobs;
using namespace gyre::model;

int main(int argc, char* argv[])
{
    QCoreApplication application(argc, argv);
    const QStringList arguments = QCoreApplication::arguments();
    if (arguments.size() != 3)
        return 2;
    if (arguments[1] == QStringLiteral("--recover") || arguments[1] == QStringLiteral("--idle")) {
        const bool recover = arguments[1] == QStringLiteral("--recover");
        const std::vector<RecoveryFile> files = recover ? Autosave::recoverableFiles(arguments[2]) : std::vector<RecoveryFile>{};
        Document document;
        Autosave autosave(document, arguments[2], std::chrono::hours(1));
        if (recover) {
            if (files.empty())
                return 1;
            autosave.recover(files.front());
        }
        std::_Exit(0);
    }
    Document document;
    document.save(arguments[2]);
    SceneObject object;
    object.id = 1;
    object.name = QStringLiteral("unsaved work");
    document.undoStack().push(new ImportObjectsCommand(document, {object}));
    Autosave autosave(document, arguments[1], std::chrono::milliseconds(10));
    QObject::connect(&autosave, &Autosave::autosaved, [] { std::_Exit(0); });
    QObject::connect(&autosave, &Autosave::autosaveFailed, [] { std::_Exit(1); });
    return QCoreApplication::exec();
}
