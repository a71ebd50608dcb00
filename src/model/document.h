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
//
// One change signal. Every edit of the scene, undoable or a whole new scene, is announced by
// changed(object, changes): the object it touched (kNoObject for the scene as a whole) and what of
// it changed. A view connects once and reads what it needs from the flags, rather than following a
// signal per kind of edit. The other signals are not edits of the scene: the current time (scrubbing
// is looking, and arrives at every frame of playback), the modified state and the file path (the
// document's relation to its file), and a gesture's end (the artist letting go). They stay apart so
// that a view that redraws on edits is not woken by playback, and the reverse.
//
// The evaluated motion of each track (motion()) is owned here, built once per change of its track
// and shared by every view and job (motion_cache.h).

#include "model/motion_cache.h"
#include "model/scene.h"

#include <QFlags>
#include <QObject>
#include <QString>
#include <QUndoStack>

#include <cstdint>
#include <memory>
#include <vector>

namespace gyre::model {

// What an edit changed, for Document::changed. The object flags come with the object's id; Scene
// and SceneSettings with kNoObject.
enum class Change {
    Object = 1 << 0,        // name, parent (and with it the order of objects), mesh
    Keyframes = 1 << 1,
    TrackSettings = 1 << 2, // interpolation, subdivision
    Sketch = 1 << 3,        // strokes, magnitude, pattern, window, fit parameters, the applied fit
    Added = 1 << 4,         // the object is new (or back, by undo)
    Removed = 1 << 5,       // the object is gone; document.object(id) is null
    SceneSettings = 1 << 6, // fps, time range
    Scene = 1 << 7,         // the whole scene was replaced (clear, load, recover): rebuild from scene()
    Gravity = 1 << 8,       // the scene's gravity: every ballistic track moves anew (with kNoObject)
};
Q_DECLARE_FLAGS(Changes, Change)
Q_DECLARE_OPERATORS_FOR_FLAGS(Changes)

// The changes after which an object's track moves differently (or is gone), so its motion is rebuilt.
inline constexpr Changes kMotionChanges =
    Changes(Change::Keyframes) | Change::TrackSettings | Change::Sketch | Change::Added | Change::Removed | Change::Scene |
    Change::Gravity;

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
    // The evaluated motion of the object's track as it is now, shared: every caller until the track
    // next changes gets the same one, built once. Null for an unknown object.
    std::shared_ptr<const SharedTrackMotion> motion(ObjectId id) const;
    // How many track motions have been built (motion_cache.h), for tests that count rebuilds.
    std::size_t motionBuilds() const { return motions_.builds(); }

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
    // The scene changed: `object` (kNoObject for Change::Scene and Change::SceneSettings) and what of
    // it. The document's motion() already reflects the change.
    void changed(gyre::model::ObjectId object, gyre::model::Changes changes);
    void currentTimeChanged(double seconds);
    void modifiedChanged(bool modified);
    void filePathChanged(const QString& path);
    // `gesture` ended; isGestureOpen() already tells whether another is still open.
    void gestureEnded(gyre::model::GestureId gesture);

private:
    friend class DocumentEditor;

    void replaceScene(Scene scene, const QString& filePath, bool modified);
    void setFilePath(const QString& path);
    // Forgets the motions the change makes stale, then emits changed.
    void notifyChanged(ObjectId object, Changes changes);

    Scene scene_;
    QUndoStack undoStack_;
    QString filePath_;
    std::vector<GestureId> openGestures_;
    GestureId lastGesture_ = kNoGesture;
    mutable MotionCache motions_; // filled on demand by the const motion()
};

} // namespace gyre::model
