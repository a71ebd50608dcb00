// A session that crashes: it edits a document, waits for its first autosave and ends at once, with no
// destructors run, as a crash would. tst_autosave starts it to leave a crashed session's files behind.
// Usage: autosave_crasher DIRECTORY DOCUMENT_PATH

#include "model/autosave.h"
#include "model/commands/import_objects_command.h"

#include <QCoreApplication>

#include <chrono>
#include <cstdlib>

using namespace gyre::model;

int main(int argc, char* argv[])
{
    QCoreApplication application(argc, argv);
    const QStringList arguments = QCoreApplication::arguments();
    if (arguments.size() != 3)
        return 2;
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
