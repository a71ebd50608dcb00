// Each command on its own: what it changes, what it refuses, and which of the document's signals it
// emits (tst_gestures: how edits within a gesture merge into one undo step). Also the document's own
// state: the current time outside the undo history, and the modified state that follows the stack's
// clean state.

#include "model_test_support.h"

#include "model/commands/add_stroke_command.h"
#include "model/commands/apply_euler_filter_command.h"
#include "model/commands/apply_fit_result_command.h"
#include "model/commands/remove_fit_command.h"
#include "model/commands/delete_object_command.h"
#include "model/commands/edit_stroke_command.h"
#include "model/commands/erase_stroke_command.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/set_keyframe_time_command.h"
#include "model/commands/rename_object_command.h"
#include "model/commands/set_mass_override_command.h"
#include "model/object_mass.h"
#include "model/commands/set_object_visibility_command.h"
#include "model/commands/reparent_object_command.h"
#include "model/commands/reparent_object_in_place_command.h"
#include "model/commands/retime_keyframes_command.h"
#include "model/commands/set_fit_parameter_command.h"
#include "model/commands/set_fit_window_command.h"
#include "model/commands/set_interpolation_command.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/commands/set_keyframe_position_command.h"
#include "model/commands/set_magnitude_curve_command.h"
#include "model/commands/set_pattern_command.h"
#include "model/commands/set_subdivision_command.h"
#include "model/commands/set_time_range_command.h"
#include "model/commands/replace_keyframes_command.h"
#include "model/key_edits.h"
#include "model/commands/step_ballistic_solution_command.h"
#include "model/commands/toggle_keyframe_constraint_command.h"
#include "model/gesture.h"
#include "model/input_error.h"
#include "model/project_file.h"
#include "model/scene_queries.h"
#include "model/track_evaluation.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

using namespace gyre;
using namespace gyre::model;
using gyre::model::test::deleteKeyframe;
using gyre::model::test::insertKeyframe;

namespace {

// An object with keys at the given times, each turned a little further about z.
SceneObject objectWithKeys(ObjectId id, std::vector<double> times, ObjectId parent = kNoObject)
{
    SceneObject object;
    object.id = id;
    object.name = QStringLiteral("object %1").arg(id);
    object.parent = parent;
    for (double time : times)
        object.track.keys.push_back(
            {time, {Eigen::Quaterniond(Eigen::AngleAxisd(time, Eigen::Vector3d::UnitZ())), {time, 0, 0}}, true});
    return object;
}

// Imports the objects (batch ids as given) and returns their scene ids.
std::vector<ObjectId> import(Document& document, std::vector<SceneObject> objects)
{
    auto* command = new ImportObjectsCommand(document, std::move(objects));
    const std::vector<ObjectId> ids = command->ids();
    document.undoStack().push(command);
    return ids;
}

std::vector<double> keyTimes(const Document& document, ObjectId id)
{
    std::vector<double> times;
    for (const Keyframe& key : document.object(id)->track.keys)
        times.push_back(key.time);
    return times;
}

// Whether constructing the command throws std::invalid_argument with `message` in it.
bool refuses(const std::function<void()>& makeCommand, const QString& message)
{
    try {
        makeCommand();
    } catch (const std::invalid_argument& error) {
        if (QString::fromUtf8(error.what()).contains(message))
            return true;
        qWarning("refused with another message: %s", error.what());
        return false;
    }
    return false;
}

// Records what a document says changed: "Flag:id" for each flag of each changed(), in the order of
// the Change flags, and "currentTimeChanged" for each move of the current time.
struct SignalCounts {
    explicit SignalCounts(Document& document)
    {
        QObject::connect(&document, &Document::changed, &context, [this](ObjectId object, Changes changes) {
            const std::pair<Change, const char*> flags[] = {
                {Change::Object, "Object"}, {Change::Keyframes, "Keyframes"}, {Change::TrackSettings, "TrackSettings"},
                {Change::Sketch, "Sketch"}, {Change::Added, "Added"}, {Change::Removed, "Removed"},
                {Change::SceneSettings, "SceneSettings"}, {Change::Scene, "Scene"}};
            for (const auto& [flag, name] : flags)
                if (changes.testFlag(flag))
                    lines << QStringLiteral("%1:%2").arg(QString::fromLatin1(name)).arg(object);
        });
        QObject::connect(&document, &Document::currentTimeChanged, &context,
                         [this] { lines << QStringLiteral("currentTimeChanged"); });
    }

    QStringList summary() const { return lines; }

    QObject context; // disconnects when the counts go
    QStringList lines;
};

} // namespace

class TstCommands : public QObject {
    Q_OBJECT

private slots:
    void insertKeyframeKeepsTimeOrder();
    void insertKeyframeRefusesBadKeys();
    void deleteKeyframeTakesItOut();
    void moveKeyframeStaysBetweenNeighbours();
    void retimeMapsTheWholeTrack();
    void keyframeEdits();
    void trackSettings();
    void budgetsRefuseUnboundedTracks();
    void stepBallisticSolutionCyclesOneSpan();
    void strokes();
    void sketchSettings();
    void applyFitResult();
    void removeFitRestoresWhatEveryFitMoved();
    void importRemapsIdsAndKeepsSharedMeshes();
    void importRefusesBadBatches();
    void importGivesSkinsTheirJointsSceneIds();
    void renameObject();
    void massOverrideTakesOnlyABodysProperties();
    void reparentKeepsParentsFirst();
    void reparentRefusesCycles();
    void reparentInPlaceKeepsTheWorldPoseAtEveryKey();
    void deleteRemovesTheSubtree();
    void timeRange();
    void signalsSayWhatChanged_data();
    void signalsSayWhatChanged();
    void currentTimeIsNotUndoable();
    void modifiedFollowsTheSavedState();
};

void TstCommands::insertKeyframeKeepsTimeOrder()
{
    Document document;
    const ObjectId id = import(document, {objectWithKeys(1, {0, 2})}).front();
    document.undoStack().push(insertKeyframe(document, id, {1, {}, true}).release());
    document.undoStack().push(insertKeyframe(document, id, {-1, {}, true}).release());
    document.undoStack().push(insertKeyframe(document, id, {5, {}, true}).release());
    QCOMPARE(keyTimes(document, id), (std::vector<double>{-1, 0, 1, 2, 5}));
    document.undoStack().undo();
    document.undoStack().undo();
    QCOMPARE(keyTimes(document, id), (std::vector<double>{0, 1, 2}));
}

void TstCommands::insertKeyframeRefusesBadKeys()
{
    Document document;
    const ObjectId id = import(document, {objectWithKeys(1, {0, 2})}).front();
    const auto add = [&](Keyframe key) { insertKeyframe(document, id, key); };
    // The window keys no object at a time it has a key at (tst_main_window); a key list that holds
    // two keys at one time is refused.
    QVERIFY(refuses([&] { ReplaceKeyframesCommand(document, {{id, objectWithKeys(1, {0, 2, 2}).track.keys}}, ReplaceKeyframesCommand::Edit::Insert); },
                    "time 2 does not come after the time before it, 2"));
    QVERIFY(refuses([&] { add({std::nan(""), {}, true}); }, "is not a finite number"));
    QVERIFY(refuses([&] { add({1, {Eigen::Quaterniond(0, 0, 0, 0), Eigen::Vector3d::Zero()}, true}); }, "the quaternion is zero"));
    QVERIFY(refuses([&] { add({1, {Eigen::Quaterniond(2, 0, 0, 0), Eigen::Vector3d::Zero()}, true}); }, "has length 2"));
    QVERIFY(refuses([&] { ReplaceKeyframesCommand(document, {{99, objectWithKeys(1, {1}).track.keys}}, ReplaceKeyframesCommand::Edit::Insert); },
                    "no object 99"));
    QCOMPARE(document.undoStack().count(), 1);

    // A quaternion that drifted a little off unit length is normalised.
    document.undoStack().push(insertKeyframe(document, id, {1, {Eigen::Quaterniond(0, 0, 1.0005, 0), Eigen::Vector3d::Zero()}, true}).release());
    QCOMPARE(document.object(id)->track.keys[1].pose.orientation.coeffs(), Eigen::Vector4d(0, 1, 0, 0));
}

void TstCommands::deleteKeyframeTakesItOut()
{
    Document document;
    const ObjectId id = import(document, {objectWithKeys(1, {0, 1, 2})}).front();
    const Keyframe removed = document.object(id)->track.keys[1];
    document.undoStack().push(deleteKeyframe(document, id, 1).release());
    QCOMPARE(keyTimes(document, id), (std::vector<double>{0, 2}));
    document.undoStack().undo();
    QCOMPARE(keyTimes(document, id), (std::vector<double>{0, 1, 2}));
    QCOMPARE(document.object(id)->track.keys[1].pose.position, removed.pose.position);
}

void TstCommands::moveKeyframeStaysBetweenNeighbours()
{
    Document document;
    const ObjectId id = import(document, {objectWithKeys(1, {0, 1, 2})}).front();
    QVERIFY(refuses([&] { SetKeyframeTimeCommand(document, id, 1, 2); }, "moves only between its neighbours at 0 and 2 s"));
    QVERIFY(refuses([&] { SetKeyframeTimeCommand(document, id, 1, -0.5); }, "not to -0.5 s"));
    document.undoStack().push(new SetKeyframeTimeCommand(document, id, 2, 100));
    document.undoStack().push(new SetKeyframeTimeCommand(document, id, 0, -100));
    QCOMPARE(keyTimes(document, id), (std::vector<double>{-100, 1, 100}));
}

void TstCommands::retimeMapsTheWholeTrack()
{
    Document document;
    SceneObject object = objectWithKeys(1, {0, 1, 2});
    SketchState& sketch = object.track.sketch;
    sketch.directionStrokes = {{{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()}, {0.5, 1.5}}};
    sketch.magnitude = {{0, 1}, {2, 3}};
    sketch.window = std::pair{0.5, 1.5};
    sketch.fittedCurve = {{1, Eigen::Quaterniond::Identity(), Eigen::Quaterniond(0, 1, 2, 3)}};
    const ObjectId id = import(document, {object}).front();
    document.undoStack().push(new RetimeKeyframesCommand(document, id, 2, 1)); // t' = 2t + 1
    const MotionTrack& track = document.object(id)->track;
    QCOMPARE(keyTimes(document, id), (std::vector<double>{1, 3, 5}));
    QCOMPARE(track.sketch.directionStrokes[0].times, (std::vector<double>{2, 4}));
    QCOMPARE(track.sketch.magnitude[1].time, 5.0);
    QCOMPARE(track.sketch.magnitude[1].magnitude, 3.0);
    QCOMPARE(*track.sketch.window, (std::pair{2.0, 4.0}));
    QCOMPARE(track.sketch.fittedCurve[0].time, 3.0);
    // dq/dt' = (dq/dt)/2
    QCOMPARE(track.sketch.fittedCurve[0].derivative.coeffs(), Eigen::Vector4d(0.5, 1, 1.5, 0));
    QVERIFY(refuses([&] { RetimeKeyframesCommand(document, id, 0, 1); }, "0 is not positive"));
    QVERIFY(refuses([&] { RetimeKeyframesCommand(document, id, 1e308, 0); }, "is beyond ±1e+06 s"));
}

void TstCommands::keyframeEdits()
{
    Document document;
    const ObjectId id = import(document, {objectWithKeys(1, {0, 1})}).front();
    document.undoStack().push(new SetKeyframePositionCommand(document, id, 1, {4, 5, 6}));
    document.undoStack().push(new ToggleKeyframeConstraintCommand(document, id, 1));
    const Keyframe& key = document.object(id)->track.keys[1];
    QCOMPARE(key.pose.position, Eigen::Vector3d(4, 5, 6));
    QVERIFY(!key.constrained);
    document.undoStack().undo();
    QVERIFY(document.object(id)->track.keys[1].constrained);
    QVERIFY(refuses([&] { SetKeyframePositionCommand(document, id, 0, {0, INFINITY, 0}); }, "not all components are finite"));
    QVERIFY(refuses([&] { SetKeyframeOrientationCommand(document, id, 2, Eigen::Quaterniond::Identity()); }, "has no keyframe 2"));
}

void TstCommands::trackSettings()
{
    Document document;
    const ObjectId id = import(document, {objectWithKeys(1, {0})}).front();
    document.undoStack().push(new SetInterpolationCommand(document, id, InterpolationMethod::Screw));
    const SubdivisionSettings settings{SubdivisionScheme::Jarek, 5, false, true};
    document.undoStack().push(new SetSubdivisionCommand(document, id, settings));
    const MotionTrack& track = document.object(id)->track;
    QCOMPARE(track.interpolation, InterpolationMethod::Screw);
    QCOMPARE(track.subdivision.scheme, SubdivisionScheme::Jarek);
    QCOMPARE(track.subdivision.levels, 5);
    QVERIFY(!track.subdivision.cyclic);
    QVERIFY(refuses([&] { SetSubdivisionCommand(document, id, {SubdivisionScheme::Jarek, 17, true, false}); },
                    "levels 17 are outside 0 to 16"));
}

// Next and previous flight step the span at the time given, one undo step each, wrapping around its count;
// the other span keeps its flight, and a track that is not ballistic has nothing to step. A key added in an
// earlier span leaves the stepped span's flight with that span, now the third.
void TstCommands::stepBallisticSolutionCyclesOneSpan()
{
    Document document;
    SceneObject object = objectWithKeys(1, {0, 1, 2});
    object.track.interpolation = InterpolationMethod::Ballistic;
    const ObjectId id = import(document, {object, objectWithKeys(2, {0, 1})}).front();
    const auto choices = [&] { return document.motion(id)->motion().flightChoices(); };
    const std::vector<TrackMotion::FlightChoice> before = choices();
    QCOMPARE(before.size(), std::size_t(2));
    const std::size_t count = before[1].count;
    QVERIFY(count >= 2);
    const std::optional<SharedVector<Keyframe>> next = StepBallisticSolutionCommand::stepped(document, id, 1.5, 1);
    QVERIFY(next.has_value());
    const int steps = document.undoStack().count();
    document.undoStack().push(new StepBallisticSolutionCommand(document, id, *next));
    QCOMPARE(document.undoStack().count(), steps + 1);
    QCOMPARE(choices()[1].chosen, (before[1].chosen + 1) % count);
    QCOMPARE(choices()[0].chosen, before[0].chosen);
    const std::size_t stepped = choices()[1].chosen;
    const Keyframe between{0.5, document.motion(id)->motion().at(0.5), true};
    document.undoStack().push(insertKeyframe(document, id, between).release());
    QCOMPARE(choices().size(), std::size_t(3));
    QCOMPARE(choices()[2].chosen, stepped);
    document.undoStack().undo();
    document.undoStack().undo();
    QCOMPARE(choices()[1].chosen, before[1].chosen);
    const std::optional<SharedVector<Keyframe>> previous = StepBallisticSolutionCommand::stepped(document, id, 1.5, -1);
    QVERIFY(previous.has_value());
    QCOMPARE((*previous)[1].flightSolution, static_cast<int>((before[1].chosen + count - 1) % count));
    QVERIFY(!StepBallisticSolutionCommand::stepped(document, id + 1, 0.5, 1).has_value());
}

// Every command that changes the keys' count, the levels or the interpolation of a track keeps it within
// the pose budget, n·2^L ≤ 1,048,576, and names what it would have needed.
void TstCommands::budgetsRefuseUnboundedTracks()
{
    Document document;
    std::vector<double> thousand;
    for (int k = 0; k < 1000; ++k)
        thousand.push_back(0.01 * k);
    SceneObject screw = objectWithKeys(1, thousand);
    screw.track.interpolation = InterpolationMethod::Screw;
    const ObjectId id = import(document, {screw}).front();
    QVERIFY(refuses([&] { SetSubdivisionCommand(document, id, {SubdivisionScheme::Jarek, 16, true, false}); },
                    "1,000 keys at 16 levels make 65,536,000 poses; the budget is 1,048,576"));
    document.undoStack().push(new SetSubdivisionCommand(document, id, {SubdivisionScheme::Jarek, 10, true, false}));
    QCOMPARE(document.object(id)->track.subdivision.levels, 10); // 1,024,000 poses: within

    // 16 keys at 16 levels are exactly the budget; a 17th key is one too many.
    SceneObject full = objectWithKeys(2, std::vector<double>(thousand.begin(), thousand.begin() + 16));
    full.track.interpolation = InterpolationMethod::Screw;
    full.track.subdivision.levels = 16;
    const ObjectId fullId = import(document, {full}).front();
    QVERIFY(refuses([&] { insertKeyframe(document, fullId, {20.0, {}, true}); },
                    "17 keys at 16 levels make 1,114,112 poses; the budget is 1,048,576"));

    // Levels wait unused on a Hermite track; turning it into a screw track would subdivide them.
    SceneObject hermite = objectWithKeys(3, thousand);
    hermite.track.subdivision.levels = 16;
    const ObjectId hermiteId = import(document, {hermite}).front();
    QVERIFY(refuses([&] { SetInterpolationCommand(document, hermiteId, InterpolationMethod::Screw); },
                    "1,000 keys at 16 levels make 65,536,000 poses"));
    hermite.track.interpolation = InterpolationMethod::Screw;
    QVERIFY(refuses([&] { ImportObjectsCommand(document, {hermite}); }, "1,000 keys at 16 levels make 65,536,000 poses"));
    // A ballistic track solves a free flight for each span: 64 keys at most.
    QVERIFY(refuses([&] { SetInterpolationCommand(document, hermiteId, InterpolationMethod::Ballistic); },
                    "1,000 keys on a ballistic track, which solves a free flight for each span; it may hold 64"));

    // Fitted curves without a direction, and times past the bound.
    const Eigen::Quaterniond still(0, 0, 0, 0);
    FitResult zero{{{0, Eigen::Quaterniond::Identity(), still}, {1, Eigen::Quaterniond(0, 0, 0, 0), still}},
                   document.object(id)->track.keys};
    QVERIFY(refuses([&] { ApplyFitResultCommand(document, id, zero); }, "the value has length 0"));
    QVERIFY(refuses([&] { SetKeyframeTimeCommand(document, id, 999, 1e300); }, "time 1e+300 is beyond ±1e+06 s"));
    QVERIFY(refuses([&] { SetTimeRangeCommand(document, {24, 0, 1e6}); }, "make 24,000,000 frames; the budget is 16,777,216"));
}

void TstCommands::strokes()
{
    Document document;
    const ObjectId id = import(document, {objectWithKeys(1, {0})}).front();
    QUndoStack& stack = document.undoStack();
    stack.push(new AddStrokeCommand(document, id, {{Eigen::Vector3d(0, 0, 1.0002)}, {}}));
    stack.push(new AddStrokeCommand(document, id, {{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()}, {0, 1}}));
    const auto strokes = [&] { return document.object(id)->track.sketch.directionStrokes; };
    QCOMPARE(strokes().size(), std::size_t{2});
    QCOMPARE(strokes()[0].points[0], Eigen::Vector3d::UnitZ()); // normalised
    {
        Gesture edit(document);
        edit.push(new EditStrokeCommand(document, id, 0, {{Eigen::Vector3d::UnitY()}, {}}));
        edit.push(new EditStrokeCommand(document, id, 0, {{-Eigen::Vector3d::UnitY()}, {}}));
    }
    QCOMPARE(stack.count(), 4); // the two edits merged
    stack.push(new EraseStrokeCommand(document, id, 0));
    QCOMPARE(strokes().size(), std::size_t{1});
    QCOMPARE(strokes()[0].times, (std::vector<double>{0, 1}));
    stack.undo();
    QCOMPARE(strokes()[0].points[0], -Eigen::Vector3d::UnitY());
    QVERIFY(refuses([&] { AddStrokeCommand(document, id, {}); }, "needs at least one point"));
    QVERIFY(refuses([&] { AddStrokeCommand(document, id, {{Eigen::Vector3d::UnitX()}, {0, 1}}); }, "no times or one per point"));
    QVERIFY(refuses([&] { EraseStrokeCommand(document, id, 2); }, "has no stroke 2"));
}

void TstCommands::sketchSettings()
{
    Document document;
    const ObjectId id = import(document, {objectWithKeys(1, {0})}).front();
    QUndoStack& stack = document.undoStack();
    stack.push(new SetMagnitudeCurveCommand(document, id, {{0, 1}, {1, 2}}));
    stack.push(new SetPatternCommand(document, id, {{0.1, 0.2}}, 3));
    stack.push(new SetFitWindowCommand(document, id, std::pair{1.0, 2.0}));
    stack.push(new SetFitParameterCommand(document, id, FitParameter::Delta, 0.25));
    const SketchState& sketch = document.object(id)->track.sketch;
    QCOMPARE(sketch.magnitude.size(), std::size_t{2});
    QCOMPARE(sketch.patternRepeat, 3);
    QCOMPARE(sketch.pattern.front(), Eigen::Vector2d(0.1, 0.2));
    QCOMPARE(*sketch.window, (std::pair{1.0, 2.0}));
    QCOMPARE(sketch.delta, 0.25);
    stack.push(new SetFitWindowCommand(document, id, std::nullopt));
    QVERIFY(!document.object(id)->track.sketch.window);
    QVERIFY(refuses([&] { SetMagnitudeCurveCommand(document, id, {{0, -1}}); }, "-1 is negative"));
    QVERIFY(refuses([&] { SetMagnitudeCurveCommand(document, id, {{1, 1}, {1, 1}}); }, "does not come after"));
    QVERIFY(refuses([&] { SetPatternCommand(document, id, {}, -1); }, "repeat count -1 is negative"));
    QVERIFY(refuses([&] { SetFitWindowCommand(document, id, std::pair{2.0, 1.0}); }, "does not come after"));
    QVERIFY(refuses([&] { SetFitParameterCommand(document, id, FitParameter::Delta, 0); }, "0 is not positive"));
    QVERIFY(refuses([&] { SetFitParameterCommand(document, id, FitParameter::Alpha, -1); }, "-1 is negative"));
}

void TstCommands::applyFitResult()
{
    Document document;
    const ObjectId id = import(document, {objectWithKeys(1, {0, 1})}).front();
    FitResult result{{{0, Eigen::Quaterniond::Identity(), Eigen::Quaterniond(0, 0, 0, 1)},
                      {1, Eigen::Quaterniond::Identity(), Eigen::Quaterniond(0, 0, 0, 1)}},
                     {{0, {}, true}, {0.5, {}, false}, {1, {}, true}}};
    document.undoStack().push(new ApplyFitResultCommand(document, id, result));
    QCOMPARE(keyTimes(document, id), (std::vector<double>{0, 0.5, 1}));
    QCOMPARE(document.object(id)->track.sketch.fittedCurve.size(), std::size_t{2});
    document.undoStack().undo();
    QCOMPARE(keyTimes(document, id), (std::vector<double>{0, 1}));
    QVERIFY(document.object(id)->track.sketch.fittedCurve.empty());
    result.curve[1].time = 0;
    QVERIFY(refuses([&] { ApplyFitResultCommand(document, id, result); }, "does not come after"));
}

// Two fits in a row, the second moving a key the first did not and one it did: Remove fit gives back
// every key as it was before the first fit, exactly, as one undo step.
void TstCommands::removeFitRestoresWhatEveryFitMoved()
{
    Document document;
    const ObjectId id = import(document, {objectWithKeys(1, {0, 1, 2, 3})}).front();
    const std::vector<Keyframe> keyed = document.object(id)->track.keys;
    const std::vector<HermiteControlPoint> curve = {{0, Eigen::Quaterniond::Identity(), Eigen::Quaterniond(0, 0, 0, 1)},
                                                    {3, Eigen::Quaterniond::Identity(), Eigen::Quaterniond(0, 0, 0, 1)}};
    const auto turned = [](std::vector<Keyframe> keys, std::size_t key, double angle) {
        keys[key].pose.orientation = keys[key].pose.orientation * Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX());
        return keys;
    };
    document.undoStack().push(new ApplyFitResultCommand(document, id, {curve, turned(keyed, 1, 0.3)}));
    QCOMPARE(document.object(id)->track.sketch.keysBeforeFit.size(), std::size_t{1});
    const std::vector<Keyframe> firstFit = document.object(id)->track.keys;
    document.undoStack().push(new ApplyFitResultCommand(document, id, {curve, turned(turned(firstFit, 1, 0.2), 2, -0.4)}));
    const std::vector<Keyframe> secondFit = document.object(id)->track.keys;
    const std::vector<Keyframe>& before = document.object(id)->track.sketch.keysBeforeFit;
    QCOMPARE(before.size(), std::size_t{2});
    QVERIFY(before[0].time == 1 && before[0].pose.orientation.coeffs() == keyed[1].pose.orientation.coeffs());
    QVERIFY(before[1].time == 2 && before[1].pose.orientation.coeffs() == keyed[2].pose.orientation.coeffs());

    const auto keysAre = [&](const std::vector<Keyframe>& expected) {
        const std::vector<Keyframe>& keys = document.object(id)->track.keys;
        return std::ranges::equal(keys, expected, [](const Keyframe& a, const Keyframe& b) {
            return a.time == b.time && a.pose.orientation.coeffs() == b.pose.orientation.coeffs() &&
                   a.pose.position == b.pose.position && a.constrained == b.constrained;
        });
    };
    const int steps = document.undoStack().count();
    document.undoStack().push(new RemoveFitCommand(document, id));
    QCOMPARE(document.undoStack().count(), steps + 1);
    QVERIFY(keysAre(keyed));
    QVERIFY(document.object(id)->track.sketch.fittedCurve.empty());
    QVERIFY(document.object(id)->track.sketch.keysBeforeFit.empty());
    document.undoStack().undo();
    QVERIFY(keysAre(secondFit));
    QCOMPARE(document.object(id)->track.sketch.keysBeforeFit.size(), std::size_t{2});
    document.undoStack().redo();
    QVERIFY(keysAre(keyed));

    // An empty fit applied leaves nothing to restore, and the file could not hold keys to restore
    // without a fit.
    document.undoStack().undo();
    document.undoStack().push(new ApplyFitResultCommand(document, id, {{}, secondFit}));
    QVERIFY(document.object(id)->track.sketch.keysBeforeFit.empty());
}

void TstCommands::importRemapsIdsAndKeepsSharedMeshes()
{
    Document document;
    import(document, {objectWithKeys(7, {0})});
    std::vector<SceneObject> batch{objectWithKeys(10, {0}), objectWithKeys(3, {0}, 10), objectWithKeys(5, {0}, 3)};
    const auto mesh = std::make_shared<Mesh>(Mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, {0, 1, 2}, {}});
    batch[0].mesh = mesh;
    batch[2].mesh = mesh;
    const std::vector<ObjectId> ids = import(document, batch);
    QCOMPARE(ids, (std::vector<ObjectId>{2, 3, 4}));
    QCOMPARE(document.object(3)->parent, ObjectId{2});
    QCOMPARE(document.object(4)->parent, ObjectId{3});
    QCOMPARE(document.object(4)->name, QStringLiteral("object 5"));
    QCOMPARE(document.object(2)->mesh.get(), document.object(4)->mesh.get());
    document.undoStack().undo();
    QCOMPARE(document.scene().objects.size(), std::size_t{1});
    document.undoStack().redo();
    QCOMPARE(objectOrder(document.scene()), (std::vector<ObjectId>{1, 2, 3, 4}));
}

void TstCommands::importRefusesBadBatches()
{
    Document document;
    const auto importing = [&](std::vector<SceneObject> batch) { ImportObjectsCommand(document, std::move(batch)); };
    QVERIFY(refuses([&] { importing({objectWithKeys(1, {0}, 2), objectWithKeys(2, {0})}); },
                    "imported object 0: its parent 2 does not come before it"));
    QVERIFY(refuses([&] { importing({objectWithKeys(1, {0}), objectWithKeys(1, {0})}); },
                    "imported object 1: its id 1 is 0 or not unique"));
    QVERIFY(refuses([&] { importing({objectWithKeys(0, {0})}); }, "its id 0 is 0 or not unique"));
    QVERIFY(refuses([&] { importing({objectWithKeys(1, {0}, 1)}); }, "its parent 1 does not come before it"));
    QVERIFY(refuses([&] { importing({objectWithKeys(1, {1, 0})}); }, "imported object 0: time 0 does not come after"));
    SceneObject badMesh = objectWithKeys(1, {0});
    badMesh.mesh = std::make_shared<Mesh>(Mesh{{{0, 0, 0}}, {}, {0, 0, 1}, {}});
    QVERIFY(refuses([&] { importing({badMesh}); }, "mesh index 1 is beyond its 1 positions"));
    QCOMPARE(document.undoStack().count(), 0);
}

void TstCommands::importGivesSkinsTheirJointsSceneIds()
{
    Document document;
    import(document, {objectWithKeys(1, {0}), objectWithKeys(2, {0})}); // ids 1 and 2 are taken
    // A batch whose mesh comes before its joints: batch ids 10 (the mesh), 20 and 30 (the joints).
    auto mesh = std::make_shared<Mesh>(Mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, {0, 1, 2}, {}});
    mesh->skin.joints = {30, 20};
    mesh->skin.inverseBinds.assign(2, Eigen::Matrix4f::Identity());
    mesh->skin.vertexJoints.assign(3, {0, 1, 0, 0});
    mesh->skin.vertexWeights.assign(3, Eigen::Vector4f(0.5F, 0.5F, 0.0F, 0.0F));
    SceneObject held = objectWithKeys(10, {0});
    held.mesh = mesh;
    SceneObject twin = objectWithKeys(40, {0});
    twin.mesh = mesh;
    const std::vector<ObjectId> ids = import(document, {held, objectWithKeys(20, {0}), objectWithKeys(30, {0}, 20), twin});
    const std::shared_ptr<const Mesh>& placed = document.object(ids[0])->mesh;
    QCOMPARE(placed->skin.joints, (std::vector<ObjectId>{ids[2], ids[1]}));
    QCOMPARE(placed->skin.vertexWeights, mesh->skin.vertexWeights);
    QCOMPARE(document.object(ids[3])->mesh, placed); // the shared mesh stays shared
    QCOMPARE(mesh->skin.joints, (std::vector<ObjectId>{30, 20})); // the batch's own mesh is not changed

    // A joint that is no object of the batch is refused before any id is taken.
    const ObjectId nextId = document.scene().nextObjectId;
    mesh->skin.joints = {30, 50};
    QVERIFY(refuses([&] { ImportObjectsCommand(document, {held, objectWithKeys(20, {0}), objectWithKeys(30, {0}, 20)}); },
                    "imported object 0: the skin's joint 50 is not an object of the scene"));
    QCOMPARE(document.scene().nextObjectId, nextId);
}

void TstCommands::massOverrideTakesOnlyABodysProperties()
{
    Document document;
    import(document, {objectWithKeys(1, {0, 1})});
    const int imported = document.undoStack().index();
    const MassProperties computed = objectMassProperties(*document.object(1)).properties;
    MassProperties typed;
    typed.mass = 2.0;
    typed.inertia = Eigen::Vector3d(1, 2, 2.5).asDiagonal();
    document.undoStack().push(new SetMassOverrideCommand(document, 1, typed));
    QCOMPARE(objectMassProperties(*document.object(1)).source, MassSource::Typed);
    QVERIFY(objectMassProperties(*document.object(1)).properties == typed);
    QCOMPARE(document.undoStack().undoText(), QStringLiteral("Set Mass Properties"));
    document.undoStack().push(new SetMassOverrideCommand(document, 1, std::nullopt));
    QCOMPARE(document.undoStack().undoText(), QStringLiteral("Mass From Mesh"));
    QVERIFY(objectMassProperties(*document.object(1)).properties == computed);
    document.undoStack().undo();
    QVERIFY(*document.object(1)->massOverride == typed);
    document.undoStack().undo();
    QVERIFY(!document.object(1)->massOverride);

    MassProperties rod = typed;
    rod.inertia = Eigen::Vector3d(1, 1, 3).asDiagonal();
    QVERIFY(refuses([&] { SetMassOverrideCommand(document, 1, rod); }, "no body has this inertia"));
    MassProperties weightless = typed;
    weightless.mass = 0.0;
    QVERIFY(refuses([&] { SetMassOverrideCommand(document, 1, weightless); }, "the mass must be a number above 0"));
    MassProperties nowhere = typed;
    nowhere.centre.x() = std::nan("");
    QVERIFY(refuses([&] { SetMassOverrideCommand(document, 1, nowhere); }, "not a finite point"));
    QCOMPARE(document.undoStack().index(), imported);
}

void TstCommands::renameObject()
{
    Document document;
    const ObjectId id = import(document, {objectWithKeys(1, {0})}).front();
    document.undoStack().push(new RenameObjectCommand(document, id, QStringLiteral("spinning top")));
    QCOMPARE(document.object(id)->name, QStringLiteral("spinning top"));
    document.undoStack().undo();
    QCOMPARE(document.object(id)->name, QStringLiteral("object 1"));
}

void TstCommands::reparentKeepsParentsFirst()
{
    Document document;
    // 1, 2 (child of 1), 3, 4 (child of 3)
    import(document, {objectWithKeys(1, {0}), objectWithKeys(2, {0}, 1), objectWithKeys(3, {0}), objectWithKeys(4, {0}, 3)});
    const Keyframe before = document.object(1)->track.keys[0];
    document.undoStack().push(new ReparentObjectCommand(document, 1, 4));
    // 1's subtree moves right after its new parent, 4.
    QCOMPARE(objectOrder(document.scene()), (std::vector<ObjectId>{3, 4, 1, 2}));
    QCOMPARE(document.object(1)->parent, ObjectId{4});
    // The track, which is relative to the parent, is kept.
    QCOMPARE(document.object(1)->track.keys[0].pose.position, before.pose.position);
    document.undoStack().undo();
    QCOMPARE(objectOrder(document.scene()), (std::vector<ObjectId>{1, 2, 3, 4}));
    QCOMPARE(document.object(1)->parent, kNoObject);
    document.undoStack().push(new ReparentObjectCommand(document, 4, kNoObject));
    QCOMPARE(document.object(4)->parent, kNoObject);
    QCOMPARE(objectOrder(document.scene()), (std::vector<ObjectId>{1, 2, 3, 4}));
}

void TstCommands::reparentRefusesCycles()
{
    Document document;
    import(document, {objectWithKeys(1, {0}), objectWithKeys(2, {0}, 1), objectWithKeys(3, {0}, 2)});
    QVERIFY(refuses([&] { ReparentObjectCommand(document, 1, 3); }, "cannot be the parent of object 1"));
    QVERIFY(refuses([&] { ReparentObjectCommand(document, 2, 2); }, "cannot be the parent of object 2"));
    QVERIFY(refuses([&] { ReparentObjectCommand(document, 2, 9); }, "no object 9"));
}

namespace {

// The world pose composed by hand up the parent chain, each track evaluated on its own.
Pose worldPoseByHand(const Scene& scene, ObjectId id, double time)
{
    Pose world;
    for (const SceneObject* object = findObject(scene, id); object != nullptr; object = findObject(scene, object->parent))
        world = TrackMotion(object->track).at(time) * world;
    return world;
}

} // namespace

void TstCommands::reparentInPlaceKeepsTheWorldPoseAtEveryKey()
{
    // 1 and 2 (child of 1) move and turn; 3 is 2's child with keys between theirs, so that the old
    // parent chain and the new parent are evaluated between their own keys; 4 is 3's child.
    SceneObject mover = objectWithKeys(1, {0, 2});
    mover.track.keys[1].pose = {Eigen::Quaterniond(Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, 2, 3).normalized())), {0, 4, 1}};
    SceneObject turner = objectWithKeys(2, {0, 1.5, 3}, 1);
    SceneObject child = objectWithKeys(3, {0.25, 0.7, 1.2, 2.9}, 2);
    child.track.keys[2].pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.8, Eigen::Vector3d::UnitX()));
    SceneObject grandchild = objectWithKeys(4, {0.7, 1.2}, 3);
    Document document;
    import(document, {mover, turner, child, grandchild});
    const QByteArray before = projectBytes(document.scene());
    const auto worldPoses = [&document](ObjectId id, ObjectId keysOf) {
        std::vector<Pose> poses;
        for (const Keyframe& key : document.object(keysOf)->track.keys)
            poses.push_back(worldPoseByHand(document.scene(), id, key.time));
        return poses;
    };
    const auto same = [](const std::vector<Pose>& a, const std::vector<Pose>& b) {
        for (std::size_t i = 0; i < a.size(); ++i)
            if (a[i].orientation.angularDistance(b[i].orientation) > 1e-9 || (a[i].position - b[i].position).norm() > 1e-9)
                return false;
        return a.size() == b.size();
    };
    for (const ObjectId newParent : {ObjectId{1}, kNoObject}) {
        const std::vector<Pose> childBefore = worldPoses(3, 3);
        const std::vector<Pose> grandchildBefore = worldPoses(4, 3);
        document.undoStack().push(new ReparentObjectInPlaceCommand(document, 3, newParent));
        QCOMPARE(document.object(3)->parent, newParent);
        QVERIFY(same(worldPoses(3, 3), childBefore));
        QVERIFY(same(worldPoses(4, 3), grandchildBefore)); // relative to 3, at 3's keys
        QCOMPARE(keyTimes(document, 3), (std::vector<double>{0.25, 0.7, 1.2, 2.9}));
    }
    // The plain reparent moves it: the check above is not true of any reparenting.
    const std::vector<Pose> unparented = worldPoses(3, 3);
    document.undoStack().push(new ReparentObjectCommand(document, 3, 2));
    QVERIFY(!same(worldPoses(3, 3), unparented));
    document.undoStack().undo();
    document.undoStack().undo();
    document.undoStack().undo();
    QCOMPARE(projectBytes(document.scene()), before);
    QVERIFY(refuses([&] { ReparentObjectInPlaceCommand(document, 1, 4); }, "cannot be the parent of object 1"));
    QVERIFY(refuses([&] { ReparentObjectInPlaceCommand(document, 9, 1); }, "no object 9"));
}

void TstCommands::deleteRemovesTheSubtree()
{
    Document document;
    import(document, {objectWithKeys(1, {0}), objectWithKeys(2, {0}, 1), objectWithKeys(3, {0}),
                      objectWithKeys(4, {0}, 2), objectWithKeys(5, {0}, 3)});
    const QByteArray before = projectBytes(document.scene());
    document.undoStack().push(new DeleteObjectCommand(document, 1));
    QCOMPARE(objectOrder(document.scene()), (std::vector<ObjectId>{3, 5}));
    document.undoStack().undo();
    QCOMPARE(projectBytes(document.scene()), before);
}

void TstCommands::timeRange()
{
    Document document;
    {
        Gesture edit(document);
        edit.push(new SetTimeRangeCommand(document, {30, 1, 5}));
        edit.push(new SetTimeRangeCommand(document, {30, 1, 6}));
    }
    QCOMPARE(document.undoStack().count(), 1);
    QCOMPARE(document.scene().fps, 30.0);
    QCOMPARE(document.scene().endTime, 6.0);
    document.undoStack().undo();
    QCOMPARE(document.scene().fps, 24.0);
    QCOMPARE(document.scene().endTime, 10.0);
    QVERIFY(refuses([&] { SetTimeRangeCommand(document, {0, 0, 1}); }, "0 is not positive"));
    QVERIFY(refuses([&] { SetTimeRangeCommand(document, {2000, 0, 1}); }, "above 1000"));
    QVERIFY(refuses([&] { SetTimeRangeCommand(document, {24, 1, 1}); }, "does not come after the start time"));
}

void TstCommands::signalsSayWhatChanged_data()
{
    using Make = std::function<QUndoCommand*(Document&)>;
    QTest::addColumn<Make>("make");
    QTest::addColumn<QStringList>("expected");
    // The document holds 1 with child 2, and 3; every object has keys at 0, 1, 2 and one stroke.
    const auto row = [](const char* name, Make make, QStringList expected) {
        QTest::newRow(name) << make << expected;
    };
    row("insert keyframe", [](Document& d) { return insertKeyframe(d, 2, {3, {}, true}).release(); }, {"Keyframes:2"});
    row("delete keyframe", [](Document& d) { return deleteKeyframe(d, 2, 0).release(); }, {"Keyframes:2"});
    row("move keyframe", [](Document& d) { return new SetKeyframeTimeCommand(d, 2, 1, 1.5); }, {"Keyframes:2"});
    row("retime", [](Document& d) { return new RetimeKeyframesCommand(d, 2, 2, 0); },
        {"Keyframes:2", "Sketch:2"});
    row("euler filter", [](Document& d) { return new ApplyEulerFilterCommand(d, 2); }, {"Keyframes:2"});
    row("orientation", [](Document& d) { return new SetKeyframeOrientationCommand(d, 2, 1, Eigen::Quaterniond::Identity()); }, {"Keyframes:2"});
    row("position", [](Document& d) { return new SetKeyframePositionCommand(d, 2, 1, Eigen::Vector3d::Zero()); }, {"Keyframes:2"});
    row("constraint", [](Document& d) { return new ToggleKeyframeConstraintCommand(d, 2, 1); }, {"Keyframes:2"});
    row("interpolation", [](Document& d) { return new SetInterpolationCommand(d, 2, InterpolationMethod::Squad); },
        {"TrackSettings:2"});
    row("subdivision", [](Document& d) { return new SetSubdivisionCommand(d, 2, {}); }, {"TrackSettings:2"});
    row("flight solution", [](Document& d) {
        SharedVector<Keyframe> keys = d.object(2)->track.keys;
        keys.edit().front().flightSolution = 1;
        return new StepBallisticSolutionCommand(d, 2, keys);
    }, {"Keyframes:2"});
    row("add stroke", [](Document& d) { return new AddStrokeCommand(d, 2, {{Eigen::Vector3d::UnitX()}, {}}); },
        {"Sketch:2"});
    row("erase stroke", [](Document& d) { return new EraseStrokeCommand(d, 2, 0); }, {"Sketch:2"});
    row("edit stroke", [](Document& d) { return new EditStrokeCommand(d, 2, 0, {{Eigen::Vector3d::UnitY()}, {}}); },
        {"Sketch:2"});
    row("magnitude", [](Document& d) { return new SetMagnitudeCurveCommand(d, 2, {}); }, {"Sketch:2"});
    row("pattern", [](Document& d) { return new SetPatternCommand(d, 2, {}, 0); }, {"Sketch:2"});
    row("window", [](Document& d) { return new SetFitWindowCommand(d, 2, std::nullopt); }, {"Sketch:2"});
    row("fit parameter", [](Document& d) { return new SetFitParameterCommand(d, 2, FitParameter::Beta, 2); },
        {"Sketch:2"});
    row("apply fit", [](Document& d) { return new ApplyFitResultCommand(d, 2, {}); },
        {"Keyframes:2", "Sketch:2"});
    row("import", [](Document& d) { return new ImportObjectsCommand(d, {objectWithKeys(1, {}), objectWithKeys(2, {}, 1)}); },
        {"Added:4", "Added:5"});
    row("rename", [](Document& d) { return new RenameObjectCommand(d, 2, QStringLiteral("x")); }, {"Object:2"});
    row("hide", [](Document& d) { return new SetObjectVisibilityCommand(d, 2, false); }, {"Object:2"});
    row("mass", [](Document& d) { return new SetMassOverrideCommand(d, 2, MassProperties{}); },
        {"Object:2", "TrackSettings:2"});
    row("reparent", [](Document& d) { return new ReparentObjectCommand(d, 2, 3); }, {"Object:2"});
    row("reparent in place", [](Document& d) { return new ReparentObjectInPlaceCommand(d, 2, 3); },
        {"Object:2", "Keyframes:2"});
    // Children go before their parents, so a view never holds an object whose parent it has dropped.
    row("delete", [](Document& d) { return new DeleteObjectCommand(d, 1); }, {"Removed:2", "Removed:1"});
    row("time range", [](Document& d) { return new SetTimeRangeCommand(d, {25, 0, 4}); }, {"SceneSettings:0"});
}

// Each command emits exactly the signals of what it changed, on redo and again on undo.
void TstCommands::signalsSayWhatChanged()
{
    using Make = std::function<QUndoCommand*(Document&)>;
    QFETCH(Make, make);
    QFETCH(QStringList, expected);
    Document document;
    std::vector<SceneObject> objects{objectWithKeys(1, {0, 1, 2}), objectWithKeys(2, {0, 1, 2}, 1),
                                     objectWithKeys(3, {0, 1, 2})};
    for (SceneObject& object : objects)
        object.track.sketch.directionStrokes = {{{Eigen::Vector3d::UnitZ()}, {}}};
    import(document, objects);

    SignalCounts redoSignals(document);
    document.undoStack().push(make(document));
    QCOMPARE(redoSignals.summary(), expected);
    SignalCounts undoSignals(document);
    document.undoStack().undo();
    QStringList undone = expected;
    undone.replaceInStrings("Added:", "Removed-");
    undone.replaceInStrings("Removed:", "Added:");
    undone.replaceInStrings("Removed-", "Removed:");
    QStringList actual = undoSignals.summary();
    std::sort(undone.begin(), undone.end());
    std::sort(actual.begin(), actual.end());
    QCOMPARE(actual, undone);
}

void TstCommands::currentTimeIsNotUndoable()
{
    Document document;
    QSignalSpy changed(&document, &Document::currentTimeChanged);
    document.setCurrentTime(2.5);
    document.setCurrentTime(2.5);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.front().front().toDouble(), 2.5);
    QCOMPARE(document.scene().currentTime, 2.5);
    QCOMPARE(document.undoStack().count(), 0);
    QVERIFY(!document.isModified());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, document.setCurrentTime(std::nan("")));
}

void TstCommands::modifiedFollowsTheSavedState()
{
    QTemporaryDir directory;
    const QString path = directory.filePath("project.gyre");
    Document document;
    QSignalSpy modified(&document, &Document::modifiedChanged);
    QSignalSpy filePath(&document, &Document::filePathChanged);
    QVERIFY(!document.isModified());
    import(document, {objectWithKeys(1, {0})});
    QVERIFY(document.isModified());
    document.save(path);
    QVERIFY(!document.isModified());
    QCOMPARE(document.filePath(), path);
    QCOMPARE(filePath.count(), 1);
    document.undoStack().undo();
    QVERIFY(document.isModified());
    document.undoStack().redo();
    QVERIFY(!document.isModified()); // back at the saved state
    QCOMPARE(modified.count(), 4);

    // A file that cannot be loaded leaves the document as it was.
    document.undoStack().push(new RenameObjectCommand(document, 1, QStringLiteral("edited")));
    const QByteArray before = projectBytes(document.scene());
    QVERIFY_THROWS_EXCEPTION(gyre::InputError, document.load(directory.filePath("missing.gyre")));
    QCOMPARE(projectBytes(document.scene()), before);
    QVERIFY(document.isModified());
    QCOMPARE(document.undoStack().count(), 2);

    SignalCounts reset(document);
    document.load(path);
    QCOMPARE(reset.summary(), QStringList{QStringLiteral("Scene:0")});
    QVERIFY(!document.isModified());
    QCOMPARE(document.undoStack().count(), 0);
    QCOMPARE(document.object(1)->name, QStringLiteral("object 1"));
}

QTEST_GUILESS_MAIN(TstCommands)
#include "tst_commands.moc"
