#include "model_test_support.h"

#include "model/commands/add_stroke_command.h"
#include "model/commands/apply_euler_filter_command.h"
#include "model/commands/apply_fit_result_command.h"
#include "model/commands/delete_object_command.h"
#include "model/commands/edit_stroke_command.h"
#include "model/commands/erase_stroke_command.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/set_keyframe_time_command.h"
#include "model/commands/rename_object_command.h"
#include "model/commands/set_mass_override_command.h"
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
#include "model/commands/toggle_keyframe_constraint_command.h"
#include "model/key_edits.h"

#include <algorithm>

namespace gyre::model::test {

namespace {

// Times on a grid of 1/8 s, so that new keys sometimes land on existing ones, which the window's Add
// Keyframe leaves as they are.
double gridTime(std::mt19937& engine) { return std::uniform_int_distribution<int>(0, 80)(engine) / 8.0; }

} // namespace

std::unique_ptr<ReplaceKeyframesCommand> insertKeyframe(Document& document, ObjectId id, const Keyframe& key)
{
    return std::make_unique<ReplaceKeyframesCommand>(document, ObjectKeys{{id, withKeys(document.object(id)->track.keys, {key})}},
                                                     ReplaceKeyframesCommand::Edit::Insert);
}

std::unique_ptr<ReplaceKeyframesCommand> deleteKeyframe(Document& document, ObjectId id, std::size_t key)
{
    return std::make_unique<ReplaceKeyframesCommand>(document, ObjectKeys{{id, withoutKeys(document.object(id)->track.keys, {key})}},
                                                     ReplaceKeyframesCommand::Edit::Delete);
}

RandomEdits::RandomEdits(unsigned seed)
    : engine_(seed)
{
}

double RandomEdits::number(double low, double high) { return std::uniform_real_distribution<double>(low, high)(engine_); }

std::size_t RandomEdits::index(std::size_t count)
{
    return std::uniform_int_distribution<std::size_t>(0, count - 1)(engine_);
}

Eigen::Quaterniond RandomEdits::rotation()
{
    std::normal_distribution<double> normal;
    return Eigen::Quaterniond(normal(engine_), normal(engine_), normal(engine_), normal(engine_)).normalized();
}

Eigen::Vector3d RandomEdits::vector()
{
    std::normal_distribution<double> normal;
    return {normal(engine_), normal(engine_), normal(engine_)};
}

Keyframe RandomEdits::keyframe(double time) { return {time, {rotation(), vector()}, number(0, 1) < 0.7}; }

std::vector<Keyframe> RandomEdits::keyframes(int count)
{
    std::vector<Keyframe> keys;
    double time = number(-1, 1);
    for (int i = 0; i < count; ++i) {
        keys.push_back(keyframe(time));
        time += number(0.01, 2);
    }
    return keys;
}

SketchState RandomEdits::sketch()
{
    SketchState sketch;
    const int strokes = std::uniform_int_distribution<int>(0, 2)(engine_);
    for (int s = 0; s < strokes; ++s) {
        DirectionStroke stroke;
        const bool timed = number(0, 1) < 0.5;
        for (int p = 0; p < 4; ++p) {
            stroke.points.push_back(vector().normalized());
            if (timed)
                stroke.times.push_back(p * 0.25 + s);
        }
        sketch.directionStrokes.push_back(stroke);
    }
    for (int m = 0; m < 3; ++m)
        sketch.magnitude.push_back({m * 0.5, number(0, 10)});
    sketch.pattern = {{number(-1, 1), number(-1, 1)}, {number(-1, 1), number(-1, 1)}};
    sketch.patternRepeat = std::uniform_int_distribution<int>(0, 5)(engine_);
    if (number(0, 1) < 0.5)
        sketch.window = std::pair{number(0, 1), number(2, 3)};
    sketch.alpha = number(0, 0.01);
    sketch.beta = number(0, 2);
    sketch.delta = number(0.01, 1);
    for (int c = 0; c < 3; ++c)
        sketch.fittedCurve.push_back({c * 0.5, rotation(), Eigen::Quaterniond(Eigen::Vector4d(vector().homogeneous()))});
    sketch.keysBeforeFit = keyframes(2);
    return sketch;
}

std::shared_ptr<const Mesh> RandomEdits::mesh()
{
    auto mesh = std::make_shared<Mesh>();
    for (int i = 0; i < 4; ++i) {
        mesh->positions.push_back(vector().cast<float>());
        mesh->normals.push_back(vector().normalized().cast<float>());
    }
    mesh->indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

MassProperties RandomEdits::massProperties()
{
    const Eigen::Vector3d size(number(0.1, 2), number(0.1, 2), number(0.1, 2));
    const Eigen::Vector3d squares = size.cwiseProduct(size);
    MassProperties properties;
    properties.mass = number(0.1, 10);
    properties.centre = vector();
    const Eigen::Matrix3d turn = rotation().toRotationMatrix();
    properties.inertia = turn *
                         (properties.mass / 12.0 *
                          Eigen::Vector3d(squares.y() + squares.z(), squares.x() + squares.z(), squares.x() + squares.y()))
                             .asDiagonal() *
                         turn.transpose();
    return properties;
}

std::vector<SceneObject> RandomEdits::objects(int count)
{
    const std::shared_ptr<const Mesh> shared = mesh();
    std::vector<SceneObject> batch;
    for (int i = 0; i < count; ++i) {
        SceneObject object;
        object.id = static_cast<ObjectId>(i + 1);
        object.name = QStringLiteral("node %1").arg(std::uniform_int_distribution<int>(0, 9)(engine_));
        object.parent = i > 0 && number(0, 1) < 0.6 ? static_cast<ObjectId>(index(static_cast<std::size_t>(i)) + 1)
                                                   : kNoObject;
        object.mesh = number(0, 1) < 0.3 ? nullptr : number(0, 1) < 0.5 ? shared : mesh();
        object.track.keys = keyframes(std::uniform_int_distribution<int>(0, 5)(engine_));
        object.track.interpolation = static_cast<InterpolationMethod>(index(6));
        object.track.subdivision = {static_cast<SubdivisionScheme>(index(4)), static_cast<int>(index(7)),
                                    number(0, 1) < 0.5, number(0, 1) < 0.5};
        object.track.sketch = sketch();
        object.visible = number(0, 1) < 0.8;
        if (number(0, 1) < 0.3)
            object.massOverride = massProperties();
        batch.push_back(object);
    }
    return batch;
}

Scene RandomEdits::scene(int count)
{
    Scene scene;
    scene.objects = objects(count);
    scene.nextObjectId = static_cast<ObjectId>(count + 1);
    scene.fps = number(1, 120);
    scene.startTime = number(-5, 0);
    scene.endTime = number(1, 50);
    scene.currentTime = number(0, 1);
    return scene;
}

EditKind RandomEdits::kind(const Document& document)
{
    constexpr std::size_t kEnoughObjects = 12;
    repeating_ = number(0, 1) < 0.3;
    if (!repeating_)
        lastKind_ = static_cast<EditKind>(index(kEditKinds));
    if (lastKind_ == EditKind::ImportObjects && document.scene().objects.size() >= kEnoughObjects)
        lastKind_ = EditKind::DeleteObject;
    return lastKind_;
}

ObjectId RandomEdits::object(const Document& document)
{
    const std::vector<SceneObject>& objects = document.scene().objects;
    if (objects.empty())
        return kNoObject;
    if (!(repeating() && document.object(lastObject_)))
        lastObject_ = objects[index(objects.size())].id;
    return lastObject_;
}

std::unique_ptr<QUndoCommand> RandomEdits::command(Document& document, EditKind kind)
{
    if (kind == EditKind::ImportObjects)
        return std::make_unique<ImportObjectsCommand>(document, objects(1 + static_cast<int>(index(3))));
    if (kind == EditKind::SetTimeRange) {
        const double start = number(-5, 5);
        return std::make_unique<SetTimeRangeCommand>(document, TimeRange{number(1, 120), start, start + number(0.1, 60)});
    }
    const ObjectId id = object(document);
    if (id == kNoObject)
        return nullptr;
    const MotionTrack& track = document.object(id)->track;
    const std::size_t keys = track.keys.size();
    const std::size_t strokes = track.sketch.directionStrokes.size();
    // The key or stroke to act on: the last one again when repeating, so that edits merge.
    const auto pick = [&](std::size_t count) {
        if (!(repeating() && lastIndex_ < count))
            lastIndex_ = index(count);
        return lastIndex_;
    };
    switch (kind) {
    case EditKind::DeleteObject:
        return std::make_unique<DeleteObjectCommand>(document, id);
    case EditKind::RenameObject:
        return std::make_unique<RenameObjectCommand>(document, id, QStringLiteral("renamed %1").arg(index(100)));
    case EditKind::SetObjectVisibility:
        return std::make_unique<SetObjectVisibilityCommand>(document, id, number(0, 1) < 0.5);
    case EditKind::SetMassOverride:
        return std::make_unique<SetMassOverrideCommand>(document, id,
                                                        number(0, 1) < 0.3 ? std::nullopt
                                                                           : std::optional(massProperties()));
    case EditKind::ReparentObject:
    case EditKind::ReparentObjectInPlace: {
        const std::vector<SceneObject>& objects = document.scene().objects;
        const ObjectId parent = number(0, 1) < 0.2 ? kNoObject : objects[index(objects.size())].id;
        if (kind == EditKind::ReparentObjectInPlace)
            return std::make_unique<ReparentObjectInPlaceCommand>(document, id, parent);
        return std::make_unique<ReparentObjectCommand>(document, id, parent);
    }
    case EditKind::InsertKeyframe: {
        const double time = gridTime(engine_);
        if (std::any_of(track.keys.begin(), track.keys.end(), [time](const Keyframe& key) { return key.time == time; }))
            return nullptr;
        return insertKeyframe(document, id, keyframe(time));
    }
    case EditKind::RetimeKeyframes:
        return std::make_unique<RetimeKeyframesCommand>(document, id, number(0.5, 2), number(-1, 1));
    case EditKind::ApplyEulerFilter:
        return std::make_unique<ApplyEulerFilterCommand>(document, id);
    case EditKind::SetInterpolation:
        return std::make_unique<SetInterpolationCommand>(document, id, static_cast<InterpolationMethod>(index(6)));
    case EditKind::SetSubdivision:
        return std::make_unique<SetSubdivisionCommand>(
            document, id,
            SubdivisionSettings{static_cast<SubdivisionScheme>(index(4)), static_cast<int>(index(8)),
                                number(0, 1) < 0.5, number(0, 1) < 0.5});
    case EditKind::AddStroke:
        return std::make_unique<AddStrokeCommand>(document, id, DirectionStroke{{vector().normalized()}, {}});
    case EditKind::SetMagnitudeCurve:
        return std::make_unique<SetMagnitudeCurveCommand>(document, id, sketch().magnitude);
    case EditKind::SetPattern:
        return std::make_unique<SetPatternCommand>(document, id, sketch().pattern, static_cast<int>(index(4)));
    case EditKind::SetFitWindow: {
        const double start = number(0, 5);
        return std::make_unique<SetFitWindowCommand>(
            document, id, number(0, 1) < 0.2 ? std::nullopt : std::optional(std::pair{start, start + number(0.1, 5)}));
    }
    case EditKind::SetFitParameter:
        return std::make_unique<SetFitParameterCommand>(document, id, static_cast<FitParameter>(pick(3)),
                                                        number(0.001, 2));
    case EditKind::ApplyFitResult:
        return std::make_unique<ApplyFitResultCommand>(
            document, id, FitResult{sketch().fittedCurve, keyframes(static_cast<int>(index(5)))});
    default:
        break;
    }
    if (kind == EditKind::EraseStroke || kind == EditKind::EditStroke) {
        if (strokes == 0)
            return nullptr;
        const std::size_t stroke = pick(strokes);
        if (kind == EditKind::EraseStroke)
            return std::make_unique<EraseStrokeCommand>(document, id, stroke);
        return std::make_unique<EditStrokeCommand>(document, id, stroke, DirectionStroke{{vector().normalized()}, {}});
    }
    if (keys == 0)
        return nullptr;
    const std::size_t key = pick(keys);
    switch (kind) {
    case EditKind::DeleteKeyframe:
        return deleteKeyframe(document, id, key);
    case EditKind::MoveKeyframe: {
        const double earlier = key > 0 ? track.keys[key - 1].time : track.keys[key].time - 1;
        const double later = key + 1 < keys ? track.keys[key + 1].time : track.keys[key].time + 1;
        return std::make_unique<SetKeyframeTimeCommand>(document, id, key, earlier + (later - earlier) * number(0.1, 0.9));
    }
    case EditKind::SetKeyframeOrientation:
        return std::make_unique<SetKeyframeOrientationCommand>(document, id, key, rotation());
    case EditKind::SetKeyframePosition:
        return std::make_unique<SetKeyframePositionCommand>(document, id, key, vector());
    default:
        return std::make_unique<ToggleKeyframeConstraintCommand>(document, id, key);
    }
}

} // namespace gyre::model::test
