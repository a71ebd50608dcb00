// An object's rotation mode (scene.h's RotationMode, rotation_mode.h): SetRotationModeCommand converts the keys
// and the interpolation and is undone whole; the motion stays where it was at the keys (and, for the linear
// euler interpolation, everywhere); an edit that sets only a key's orientation leaves the key angles nearest its
// old ones, and undo puts the old ones back; the project file keeps the angles (two turns stay two turns) and
// refuses angles that are not finite, on a quaternion object, or that do not give their key's orientation. The
// import's Euler filter (putInEulerMode) turns a wrapped quaternion spin into a ramp of stored angles.

#include "model/commands/import_objects_command.h"
#include "model/commands/replace_keyframes_command.h"
#include "model/commands/set_interpolation_command.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/commands/set_rotation_mode_command.h"
#include "model/document.h"
#include "model/input_error.h"
#include "model/project_file.h"
#include "model/rotation_mode.h"
#include "model/track_evaluation.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <stdexcept>

using namespace gyre;
using namespace gyre::model;

namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Quaterniond aboutAxes(double x, double y, double z)
{
    // Extrinsic xyz by its definition (DESIGN.md): R = Rz(z)·Ry(y)·Rx(x).
    return Eigen::AngleAxisd(z, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(y, Eigen::Vector3d::UnitY()) *
           Eigen::AngleAxisd(x, Eigen::Vector3d::UnitX());
}

bool sameRotation(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double tolerance = 1e-9)
{
    return std::abs(std::abs(a.coeffs().dot(b.coeffs())) - 1.0) < tolerance;
}

// A tumbling object: keys 0.8 s apart, each turned about all three axes from the one before.
SceneObject tumbler()
{
    SceneObject object;
    object.name = QStringLiteral("tumbler");
    for (int k = 0; k < 5; ++k) {
        const double t = 0.8 * k;
        object.track.keys.push_back({t, {aboutAxes(0.7 * k, 0.3 * std::sin(k), 1.1 * k), {t, 0, 0}}, true});
    }
    return object;
}

ObjectId import(Document& document, SceneObject object)
{
    object.id = 1;
    auto* command = new ImportObjectsCommand(document, {std::move(object)});
    const ObjectId id = command->ids().front();
    document.undoStack().push(command);
    return id;
}

RotationMode eulerMode(const char* order = "xyz", AngleFrame frame = AngleFrame::Extrinsic)
{
    return {RotationMode::Kind::Euler, *EulerConvention::parse(order, frame)};
}

// An Euler-mode object keyed 0° then 720° about z (extrinsic xyz's third angle).
Scene spinScene()
{
    Scene scene;
    SceneObject object;
    object.id = 1;
    object.name = QStringLiteral("spinner");
    object.track.rotationMode = eulerMode();
    object.track.interpolation = InterpolationMethod::Euler;
    for (const double turns : {0.0, 2.0}) {
        Keyframe key;
        key.time = turns;
        key.eulerAngles = Eigen::Vector3d(0.0, 0.0, 2.0 * kPi * turns);
        key.pose.orientation = quaternionFromEulerAngles(*key.eulerAngles, object.track.rotationMode.convention);
        object.track.keys.push_back(key);
    }
    scene.objects.push_back(object);
    scene.nextObjectId = 2;
    return scene;
}

QString refusal(const QByteArray& bytes)
{
    try {
        parseProject(bytes, QStringLiteral("spin.gyre"));
    } catch (const InputError& error) {
        return QString::fromUtf8(error.what());
    }
    return {};
}

} // namespace

class TstRotationMode : public QObject {
    Q_OBJECT

private slots:
    void enteringEulerModeUnwrapsTheKeysAndUndoes()
    {
        Document document;
        const ObjectId id = import(document, tumbler());
        const MotionTrack before = document.object(id)->track;
        document.undoStack().push(new SetRotationModeCommand(document, id, eulerMode("zxy", AngleFrame::Intrinsic)));
        QCOMPARE(document.undoStack().undoText(), QStringLiteral("Set Rotation Mode"));
        const MotionTrack& after = document.object(id)->track;
        QVERIFY(after.rotationMode.isEuler());
        QCOMPARE(after.interpolation, InterpolationMethod::EulerCubic);
        // The Euler filter's angles, computed here from the orientations.
        std::vector<Eigen::Quaterniond> rotations;
        for (const Keyframe& key : before.keys)
            rotations.push_back(key.pose.orientation);
        const auto expected = unwrappedEulerAngles(rotations, after.rotationMode.convention);
        for (std::size_t k = 0; k < after.keys.size(); ++k) {
            QVERIFY(after.keys[k].eulerAngles.has_value());
            QVERIFY((*after.keys[k].eulerAngles - expected[k]).norm() < 1e-12);
            QCOMPARE(after.keys[k].pose.orientation.coeffs(), before.keys[k].pose.orientation.coeffs());
        }
        // The motion at the keys is unchanged.
        const TrackMotion was(before);
        const TrackMotion is(after);
        for (const Keyframe& key : before.keys)
            QVERIFY(sameRotation(was.at(key.time).orientation, is.at(key.time).orientation));

        document.undoStack().undo();
        const MotionTrack& undone = document.object(id)->track;
        QVERIFY(!undone.rotationMode.isEuler());
        QCOMPARE(undone.interpolation, InterpolationMethod::Hermite);
        for (const Keyframe& key : undone.keys)
            QVERIFY(!key.eulerAngles.has_value());
        document.undoStack().redo();
        QVERIFY((*document.object(id)->track.keys.back().eulerAngles - expected.back()).norm() < 1e-12);

        // Back to quaternions: the angles go, the orientations stay, hermite again.
        document.undoStack().push(new SetRotationModeCommand(document, id, RotationMode{}));
        const MotionTrack& back = document.object(id)->track;
        QCOMPARE(back.interpolation, InterpolationMethod::Hermite);
        for (std::size_t k = 0; k < back.keys.size(); ++k) {
            QVERIFY(!back.keys[k].eulerAngles.has_value());
            QCOMPARE(back.keys[k].pose.orientation.coeffs(), before.keys[k].pose.orientation.coeffs());
        }
    }

    void linearEulerMotionIsTheSameInEitherMode()
    {
        Document document;
        SceneObject object = tumbler();
        object.track.interpolation = InterpolationMethod::Euler;
        object.track.rotationMode.convention = *EulerConvention::parse("yzx", AngleFrame::Extrinsic);
        const ObjectId id = import(document, object);
        const MotionTrack quaternionTrack = document.object(id)->track;
        RotationMode mode = quaternionTrack.rotationMode;
        mode.kind = RotationMode::Kind::Euler;
        document.undoStack().push(new SetRotationModeCommand(document, id, mode));
        document.undoStack().push(new SetInterpolationCommand(document, id, InterpolationMethod::Euler));
        const TrackMotion was(quaternionTrack);
        const TrackMotion is(document.object(id)->track);
        for (double t = 0.0; t <= 3.2; t += 0.05)
            QVERIFY2(sameRotation(was.at(t).orientation, is.at(t).orientation), qPrintable(QString::number(t)));
        // A quaternion method would lose the turns: refused in Euler mode.
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 SetInterpolationCommand(document, id, InterpolationMethod::Slerp));
    }

    void aTwoTurnSpinTurnsTwice()
    {
        const Scene scene = spinScene();
        const TrackMotion motion(scene.objects.front().track);
        // At a quarter of the time half a turn (180° about z), at half the time a whole turn.
        QVERIFY(sameRotation(motion.at(0.5).orientation, aboutAxes(0, 0, kPi)));
        QVERIFY(sameRotation(motion.at(1.0).orientation, Eigen::Quaterniond::Identity()));
        QVERIFY(sameRotation(motion.at(0.25).orientation, aboutAxes(0, 0, kPi / 2)));
        QVERIFY((motion.angularVelocity(0.7) - Eigen::Vector3d(0, 0, 2 * kPi)).norm() < 1e-6);
    }

    void anOrientationAloneGetsTheNearestAnglesAndUndoRestoresThem()
    {
        Document document;
        document.undoStack().push(new ImportObjectsCommand(document, spinScene().objects));
        const ObjectId id = document.scene().objects.front().id;
        // The rotate handle turns the 720° key on by 10° about z: the key now stores 730°, not 10°.
        const double ten = 10.0 * kPi / 180.0;
        document.undoStack().push(new SetKeyframeOrientationCommand(document, id, 1, aboutAxes(0, 0, ten)));
        const Keyframe& turned = document.object(id)->track.keys[1];
        QVERIFY((*turned.eulerAngles - Eigen::Vector3d(0, 0, 4 * kPi + ten)).norm() < 1e-9);
        QVERIFY(keepsRotationMode(document.object(id)->track));
        document.undoStack().undo();
        QCOMPARE(*document.object(id)->track.keys[1].eulerAngles, Eigen::Vector3d(0, 0, 4 * kPi));

        // Keys pasted from a quaternion object have no angles: each takes those nearest the key before it.
        std::vector<Keyframe> pasted = document.object(id)->track.keys;
        Keyframe extra;
        extra.time = 3.0;
        extra.pose.orientation = aboutAxes(0, 0, 0.1);
        pasted.push_back(extra);
        document.undoStack().push(new ReplaceKeyframesCommand(document, {{id, pasted}}, ReplaceKeyframesCommand::Edit::Paste));
        QVERIFY((*document.object(id)->track.keys[2].eulerAngles - Eigen::Vector3d(0, 0, 4 * kPi + 0.1)).norm() < 1e-9);

        // Typed angles are stored as typed.
        document.undoStack().push(new SetKeyframeOrientationCommand(document, id, 0, Eigen::Vector3d(0, 0, 6 * kPi)));
        QCOMPARE(*document.object(id)->track.keys[0].eulerAngles, Eigen::Vector3d(0, 0, 6 * kPi));
        QVERIFY(sameRotation(document.object(id)->track.keys[0].pose.orientation, Eigen::Quaterniond::Identity()));
    }

    void importsEulerFilterMakesAWrappedSpinARamp()
    {
        // A spin about z by 100° a key for 8 keys (700°), as quaternions; every other stored as −q.
        MotionTrack track;
        track.interpolation = InterpolationMethod::Slerp;
        for (int k = 0; k < 8; ++k) {
            const Eigen::Quaterniond q = aboutAxes(0.0, 0.0, 100.0 * k * kPi / 180.0);
            track.keys.push_back({double(k), {k % 2 == 0 ? q : Eigen::Quaterniond(-q.coeffs()), Eigen::Vector3d::Zero()}, true});
        }
        const MotionTrack before = track;
        putInEulerMode(track, {});
        QVERIFY(track.rotationMode.isEuler());
        QCOMPARE(track.rotationMode.convention, EulerConvention{});
        QCOMPARE(track.interpolation, InterpolationMethod::Euler);
        QVERIFY(keepsRotationMode(track));
        for (int k = 0; k < 8; ++k) {
            QVERIFY((*track.keys[k].eulerAngles - Eigen::Vector3d(0.0, 0.0, 100.0 * k * kPi / 180.0)).norm() < 1e-12);
            QVERIFY(sameRotation(track.keys[k].pose.orientation, before.keys[k].pose.orientation, 1e-12));
        }
        MotionTrack cubic = before;
        cubic.interpolation = InterpolationMethod::Hermite;
        putInEulerMode(cubic, EulerConvention{{2, 1, 0}, AngleFrame::Intrinsic});
        QCOMPARE(cubic.interpolation, InterpolationMethod::EulerCubic);
        QVERIFY(keepsRotationMode(cubic));
        // Intrinsic zyx turns about z first: the spin is its first angle.
        QVERIFY(std::abs(cubic.keys.back().eulerAngles->x() - 700.0 * kPi / 180.0) < 1e-12);
    }

    void projectFilesKeepTheAngles()
    {
        const Scene scene = spinScene();
        const QByteArray bytes = projectBytes(scene);
        const Scene loaded = parseProject(bytes, QStringLiteral("spin.gyre"));
        const MotionTrack& track = loaded.objects.front().track;
        QCOMPARE(track.rotationMode, scene.objects.front().track.rotationMode);
        QCOMPARE(*track.keys[1].eulerAngles, Eigen::Vector3d(0, 0, 4 * kPi));
        QCOMPARE(projectBytes(loaded), bytes);
        // A quaternion object writes no rotation mode: files read as before.
        Scene plain;
        plain.objects.push_back(tumbler());
        plain.objects.front().id = 1;
        plain.nextObjectId = 2;
        QVERIFY(!projectBytes(plain).contains("rotationMode"));
    }

    void projectFilesRefuseBadAngles()
    {
        Scene nan = spinScene();
        nan.objects.front().track.keys.edit()[1].eulerAngles->z() = std::nan("");
        QVERIFY2(refusal(projectBytes(nan)).contains(QStringLiteral("objects[0].keyframes[1].eulerAngles: the angles are not finite")),
                 qPrintable(refusal(projectBytes(nan))));

        Scene quaternion = spinScene();
        quaternion.objects.front().track.rotationMode.kind = RotationMode::Kind::Quaternion;
        quaternion.objects.front().track.interpolation = InterpolationMethod::Hermite;
        QVERIFY2(refusal(projectBytes(quaternion)).contains(QStringLiteral("objects[0].keyframes[0].eulerAngles: angles on an object in quaternion rotation mode")),
                 qPrintable(refusal(projectBytes(quaternion))));

        Scene apart = spinScene();
        apart.objects.front().track.keys.edit()[1].eulerAngles->z() = 1.0;
        QVERIFY2(refusal(projectBytes(apart)).contains(QStringLiteral("objects[0].keyframes[1].eulerAngles: the angles do not give the key's orientation")),
                 qPrintable(refusal(projectBytes(apart))));

        Scene slerp = spinScene();
        slerp.objects.front().track.interpolation = InterpolationMethod::Slerp;
        QVERIFY2(refusal(projectBytes(slerp)).contains(QStringLiteral("objects[0].interpolation:")), qPrintable(refusal(projectBytes(slerp))));

        QByteArray badKind = projectBytes(spinScene());
        badKind.replace("\"kind\": \"euler\"", "\"kind\": \"eulex\"");
        QVERIFY2(refusal(badKind).contains(QStringLiteral("objects[0].rotationMode.kind:")), qPrintable(refusal(badKind)));
    }
};

QTEST_MAIN(TstRotationMode)
#include "tst_rotation_mode.moc"
