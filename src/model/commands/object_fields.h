#pragma once
// The fields and lists of the document that commands change, for ChangeValueCommand and
// ListEntryCommand. Each command has checked its target before it is pushed, so these look objects
// and entries up without checking again.

#include "model/document_editor.h"
#include "model/commands/change_value_command.h"
#include "model/scene.h"

#include <QString>

#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace gyre::model {

// The object with this id, which the command has made sure exists.
SceneObject& objectIn(Scene& scene, ObjectId id);
const SceneObject& objectIn(const Scene& scene, ObjectId id);

// Whether consecutive edits of a field within one gesture merge into one (ChangeValueCommand).
enum class Merge : bool { Never = false, WithinGesture = true };

// A field of an object that `Member` gives a reference to, given the object and target.index (the
// keyframe's or stroke's index, where the field belongs to one).
template <auto Member, class ValueType, Merge Merges, Change... ChangeValues>
struct MemberField {
    using Value = ValueType;
    static constexpr Changes kChanges = (Changes() | ... | ChangeValues);
    static constexpr bool kMerges = static_cast<bool>(Merges);
    static Value get(const Scene& scene, const FieldTarget& target)
    {
        return Member(objectIn(scene, target.object), target.index);
    }
    static void set(Scene& scene, const FieldTarget& target, Value value)
    {
        Member(objectIn(scene, target.object), target.index) = std::move(value);
    }
};

inline constexpr auto keyTime = [](auto& object, std::size_t key) -> auto& { return object.track.keys[key].time; };
// The orientation with the stored angles, so that undo puts back the angles an edit of the orientation alone
// changed (rotation_mode.h).
inline constexpr auto keyOrientation = [](auto& object, std::size_t key) {
    auto& keyframe = object.track.keys[key];
    return std::tie(keyframe.pose.orientation, keyframe.eulerAngles);
};
inline constexpr auto keyPosition = [](auto& object, std::size_t key) -> auto& {
    return object.track.keys[key].pose.position;
};
inline constexpr auto keyConstrained = [](auto& object, std::size_t key) -> auto& {
    return object.track.keys[key].constrained;
};
inline constexpr auto objectName = [](auto& object, std::size_t) -> auto& { return object.name; };
inline constexpr auto objectVisible = [](auto& object, std::size_t) -> auto& { return object.visible; };
inline constexpr auto objectMassOverride = [](auto& object, std::size_t) -> auto& { return object.massOverride; };
inline constexpr auto trackInterpolation = [](auto& object, std::size_t) -> auto& {
    return object.track.interpolation;
};
inline constexpr auto trackSubdivision = [](auto& object, std::size_t) -> auto& { return object.track.subdivision; };
inline constexpr auto sketchStroke = [](auto& object, std::size_t stroke) -> auto& {
    return object.track.sketch.directionStrokes[stroke];
};
inline constexpr auto sketchMagnitude = [](auto& object, std::size_t) -> auto& { return object.track.sketch.magnitude; };
inline constexpr auto sketchWindow = [](auto& object, std::size_t) -> auto& { return object.track.sketch.window; };

// The fit's parameters, chosen by target.index.
enum class FitParameter : std::size_t { Alpha, Beta, Delta };
inline constexpr auto sketchFitParameter = [](auto& object, std::size_t parameter) -> auto& {
    auto& sketch = object.track.sketch;
    const auto chosen = static_cast<FitParameter>(parameter);
    return chosen == FitParameter::Alpha ? sketch.alpha : chosen == FitParameter::Beta ? sketch.beta : sketch.delta;
};

inline constexpr auto trackKeys = [](auto& object, std::size_t) -> auto& { return object.track.keys; };

using KeyframeTimeField = MemberField<keyTime, double, Merge::WithinGesture, Change::Keyframes>;
using KeyframeOrientationField =
    MemberField<keyOrientation, KeyRotation, Merge::WithinGesture, Change::Keyframes>;
using KeyframePositionField = MemberField<keyPosition, Eigen::Vector3d, Merge::WithinGesture, Change::Keyframes>;
using KeyframesField = MemberField<trackKeys, SharedVector<Keyframe>, Merge::Never, Change::Keyframes>;
using KeyframeConstraintField = MemberField<keyConstrained, bool, Merge::Never, Change::Keyframes>;
using ObjectNameField = MemberField<objectName, QString, Merge::Never, Change::Object>;
using ObjectVisibilityField = MemberField<objectVisible, bool, Merge::Never, Change::Object>;
// The mass moves no key but the free flight of a ballistic track depends on it: its motion is rebuilt.
using MassOverrideField =
    MemberField<objectMassOverride, std::optional<MassProperties>, Merge::WithinGesture, Change::Object, Change::TrackSettings>;
using InterpolationField = MemberField<trackInterpolation, InterpolationMethod, Merge::Never, Change::TrackSettings>;
using SubdivisionField = MemberField<trackSubdivision, SubdivisionSettings, Merge::WithinGesture, Change::TrackSettings>;
using StrokeField = MemberField<sketchStroke, DirectionStroke, Merge::WithinGesture, Change::Sketch>;
using MagnitudeCurveField = MemberField<sketchMagnitude, std::vector<MagnitudePoint>, Merge::WithinGesture, Change::Sketch>;
using FitWindowField = MemberField<sketchWindow, std::optional<std::pair<double, double>>, Merge::WithinGesture, Change::Sketch>;
using FitParameterField = MemberField<sketchFitParameter, double, Merge::WithinGesture, Change::Sketch>;

// The pattern and how often it repeats, drawn and set together.
inline constexpr auto sketchPattern = [](auto& object, std::size_t) {
    return std::tie(object.track.sketch.pattern, object.track.sketch.patternRepeat);
};
using PatternField =
    MemberField<sketchPattern, std::tuple<std::vector<Eigen::Vector2d>, int>, Merge::WithinGesture, Change::Sketch>;

// The sketch's target: its direction strokes and magnitude curve, replaced together.
inline constexpr auto sketchStrokesAndMagnitude = [](auto& object, std::size_t) {
    return std::tie(object.track.sketch.directionStrokes, object.track.sketch.magnitude);
};
using SketchTargetField = MemberField<sketchStrokesAndMagnitude, std::tuple<std::vector<DirectionStroke>, std::vector<MagnitudePoint>>,
                                      Merge::Never, Change::Sketch>;

// The keyframes and the sketch together: what a retiming or an applied fit changes.
inline constexpr auto keyframesAndSketch = [](auto& object, std::size_t) {
    return std::tie(object.track.keys, object.track.sketch);
};
using KeyframesAndSketchField = MemberField<keyframesAndSketch, std::tuple<SharedVector<Keyframe>, SketchState>, Merge::Never, Change::Keyframes, Change::Sketch>;

// The rotation mode with the keys and the interpolation it converts (SetRotationModeCommand).
inline constexpr auto trackRotationMode = [](auto& object, std::size_t) {
    return std::tie(object.track.rotationMode, object.track.keys, object.track.interpolation);
};
using RotationModeField = MemberField<trackRotationMode, std::tuple<RotationMode, SharedVector<Keyframe>, InterpolationMethod>,
                                      Merge::Never, Change::Keyframes, Change::TrackSettings>;

// The parent and, because parents come before their children, the order of all objects.
struct ParentField {
    using Value = std::pair<ObjectId, std::vector<ObjectId>>;
    static constexpr Changes kChanges = Change::Object;
    static constexpr bool kMerges = false;
    static Value get(const Scene& scene, const FieldTarget& target);
    static void set(Scene& scene, const FieldTarget& target, Value value);
};

// The parent with the order of all objects, and the object's keys: what reparenting in place changes,
// since it re-expresses the keys in the new parent's frame.
struct ParentAndKeysField {
    using Value = std::pair<ParentField::Value, SharedVector<Keyframe>>;
    static constexpr Changes kChanges = Changes(Change::Object) | Change::Keyframes;
    static constexpr bool kMerges = false;
    static Value get(const Scene& scene, const FieldTarget& target);
    static void set(Scene& scene, const FieldTarget& target, Value value);
};

// The frame rate and time range of the scene.
struct TimeRange {
    double fps = 24.0;
    double startTime = 0.0;
    double endTime = 10.0;
    bool operator==(const TimeRange&) const = default;
};

struct TimeRangeField {
    using Value = TimeRange;
    static constexpr Changes kChanges = Change::SceneSettings;
    static constexpr bool kMerges = true;
    static Value get(const Scene& scene, const FieldTarget& target);
    static void set(Scene& scene, const FieldTarget& target, Value value);
};

// The scene's gravity; every ballistic track flies anew.
struct GravityField {
    using Value = Gravity;
    static constexpr Changes kChanges = Changes(Change::SceneSettings) | Change::Gravity;
    static constexpr bool kMerges = true;
    static Value get(const Scene& scene, const FieldTarget&) { return scene.gravity; }
    static void set(Scene& scene, const FieldTarget&, Value value) { scene.gravity = value; }
};

struct StrokeList {
    using Entry = DirectionStroke;
    static constexpr Changes kChanges = Change::Sketch;
    static std::vector<Entry>& of(Scene& scene, ObjectId object)
    {
        return objectIn(scene, object).track.sketch.directionStrokes;
    }
};

} // namespace gyre::model
