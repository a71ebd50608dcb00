#pragma once
// The document: one scene, the undo stack that every change to it goes through, and the file it was
// loaded from or saved to. Views read it through the const accessors and follow its signals; only
// undo commands change it, through DocumentEditor (document_editor.h).
//
// The current time is the one value outside the undo history: scrubbing is looking, not editing, so
// setCurrentTime neither pushes a command nor makes the document modified. It is still saved with the
// file, so a project opens where it was left.
//
// Gestures. A drag of the artist pushes a command at every mouse move; the document makes it one
// undo step. beginGesture hands out an id; every command pushed with that id joins the gesture's
// step (PerformGestureCommand), and consecutive edits of the same field within it merge into one.
// Pushes with another id, or with none, are steps of their own, so two drags of the same key are
// two steps. A gesture whose edits bring the document back to where it began leaves no step.
// isGestureOpen says whether the artist is still in the middle of one (a finished fit waits for
// its end, gestureEnded); gesture.h wraps begin and end for a view that holds a gesture.

#include "model/scene.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <cstdint>
#include <vector>

namespace gyre::model {

// Names one gesture; ids are never handed out twice in a session. kNoGesture: a command alone.
using GestureId = std::uint64_t;
inline constexpr GestureId kNoGesture = 0;

class Document : public QObject {
    Q_OBJECT

public:
    explicit Document(QObject* parent = nullptr);
    // Emits nothing: listeners never see a document being destroyed.
    ~Document() override;

    const Scene& scene() const { return scene_; }
    // The object with this id, or null.
    const SceneObject* object(ObjectId id) const;

    QUndoStack& undoStack() { return undoStack_; }
    const QUndoStack& undoStack() const { return undoStack_; }

    // Where the document was loaded from or last saved to; empty for a new document.
    const QString& filePath() const { return filePath_; }
    // Changed since it was loaded or saved: the undo stack is away from its clean state.
    bool isModified() const { return !undoStack_.isClean(); }

    // Pushes `command` (taking it) onto the undo stack as part of `gesture`: it joins the gesture's
    // step while that step is still the newest (nothing pushed, undone or saved in between), or
    // begins one. A gesture that has ended may be continued this way. With kNoGesture the command
    // is a step of its own, never merged with another.
    void push(QUndoCommand* command, GestureId gesture = kNoGesture);
    // A new gesture, open until endGesture.
    GestureId beginGesture();
    // Ends `gesture` and emits gestureEnded; nothing if it is not open.
    void endGesture(GestureId gesture);
    // Whether any gesture is open: the artist is in the middle of a drag.
    bool isGestureOpen() const { return !openGestures_.empty(); }
    // The gesture of the newest step on the undo stack (the one undo would take back), or
    // kNoGesture if that step belongs to none or there is none.
    GestureId newestStepGesture() const;

    // Throws std::invalid_argument for a time that is not finite.
    void setCurrentTime(double seconds);

    // A new project: untitled, unmodified, holding one object to key (a block with no mesh of its
    // own and no keys), so that the artist has something to turn without importing a file.
    void startNewProject();
    // Replaces the scene with the project at `path` and forgets the undo history. Throws InputError
    // and leaves the document untouched if the file cannot be read whole.
    void load(const QString& path);
    // Replaces the scene with the project at `path` as a new untitled document, unmodified: a
    // template such as a bundled sample (a Qt resource path works), which Save then asks a name for.
    // Throws InputError and leaves the document untouched if the file cannot be read whole.
    void loadAsUntitled(const QString& path);
    // Writes the project to `path`, which becomes the document's file, and marks this state saved.
    // Throws OutputError; a file already at `path` then keeps its contents.
    void save(const QString& path);
    // Opens a recovery copy (autosave.h) as unsaved changes to the document at `documentPath`.
    void recover(const QString& recoveryPath, const QString& documentPath);

signals:
    // The whole scene was replaced (clear, load, recover); views rebuild from scene().
    void sceneReset();
    void objectAdded(gyre::model::ObjectId id);
    void objectRemoved(gyre::model::ObjectId id);
    // Name, parent or mesh. A new parent may also move the object within scene().objects.
    void objectChanged(gyre::model::ObjectId id);
    void keyframesChanged(gyre::model::ObjectId id);
    // Interpolation or subdivision settings.
    void trackSettingsChanged(gyre::model::ObjectId id);
    void sketchChanged(gyre::model::ObjectId id);
    // Frame rate or time range.
    void sceneSettingsChanged();
    void currentTimeChanged(double seconds);
    void modifiedChanged(bool modified);
    void filePathChanged(const QString& path);
    // `gesture` ended; isGestureOpen() already tells whether another is still open.
    void gestureEnded(gyre::model::GestureId gesture);

private:
    friend class DocumentEditor;

    void replaceScene(Scene scene, const QString& filePath, bool modified);
    void setFilePath(const QString& path);

    Scene scene_;
    QUndoStack undoStack_;
    QString filePath_;
    std::vector<GestureId> openGestures_;
    GestureId lastGesture_ = kNoGesture;
};

} // namespace gyre::model
