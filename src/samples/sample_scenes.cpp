#include "samples/sample_scenes.h"

#include "fit/angular_velocity_fit.h"
#include "model/sketch_fit_problem.h"
#include "model/commands/apply_fit_result_command.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace gyre::samples {

namespace {

using model::Keyframe;
using model::Mesh;

// A solid of revolution about z: each band between consecutive profile points (radius, height) is
// a ring of quads with the band's own normal, so the profile's corners stay sharp.
Mesh latheMesh(const std::vector<Eigen::Vector2f>& profile, int segments)
{
    Mesh mesh;
    const auto around = [segments](int k) {
        const float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / static_cast<float>(segments);
        return Eigen::Vector2f(std::cos(angle), std::sin(angle));
    };
    for (std::size_t band = 0; band + 1 < profile.size(); ++band) {
        const Eigen::Vector2f& lower = profile[band];
        const Eigen::Vector2f& upper = profile[band + 1];
        // The profile's tangent (dr, dz) turned outwards: (dz, −dr).
        const Eigen::Vector2f outward = Eigen::Vector2f(upper.y() - lower.y(), lower.x() - upper.x()).normalized();
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        for (int k = 0; k <= segments; ++k) {
            const Eigen::Vector2f direction = around(k);
            const Eigen::Vector3f normal(outward.x() * direction.x(), outward.x() * direction.y(), outward.y());
            for (const Eigen::Vector2f& point : {lower, upper}) {
                mesh.positions.emplace_back(point.x() * direction.x(), point.x() * direction.y(), point.y());
                mesh.normals.push_back(normal);
            }
        }
        // Counter-clockwise seen from outside: around × up is the outward normal.
        for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(segments); ++k) {
            const std::uint32_t a = first + 2 * k;
            const std::uint32_t b = a + 2;
            mesh.indices.insert(mesh.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
        }
    }
    return mesh;
}

// A right prism over a convex polygon (counter-clockwise in xy), from z = −thickness/2 to
// +thickness/2: two fan-triangulated caps and a quad per edge, each face with its own normal.
Mesh prismMesh(const std::vector<Eigen::Vector2f>& polygon, float thickness)
{
    Mesh mesh;
    const float half = 0.5f * thickness;
    for (const float side : {-1.0f, 1.0f}) {
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        for (const Eigen::Vector2f& point : polygon) {
            mesh.positions.emplace_back(point.x(), point.y(), side * half);
            mesh.normals.emplace_back(0.0f, 0.0f, side);
        }
        // The top cap keeps the polygon's counter-clockwise turn; the bottom one is seen from below.
        for (std::uint32_t k = 1; k + 1 < static_cast<std::uint32_t>(polygon.size()); ++k) {
            if (side > 0.0f)
                mesh.indices.insert(mesh.indices.end(), {first, first + k, first + k + 1});
            else
                mesh.indices.insert(mesh.indices.end(), {first, first + k + 1, first + k});
        }
    }
    for (std::size_t edge = 0; edge < polygon.size(); ++edge) {
        const Eigen::Vector2f& a = polygon[edge];
        const Eigen::Vector2f& b = polygon[(edge + 1) % polygon.size()];
        // The edge (dx, dy) of a counter-clockwise polygon has its outside on the right: (dy, −dx).
        const Eigen::Vector2f outward = Eigen::Vector2f(b.y() - a.y(), a.x() - b.x()).normalized();
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        for (const auto& [point, height] : {std::pair(a, -half), std::pair(b, -half), std::pair(b, half), std::pair(a, half)}) {
            mesh.positions.emplace_back(point.x(), point.y(), height);
            mesh.normals.emplace_back(outward.x(), outward.y(), 0.0f);
        }
        mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
    return mesh;
}

// `part`'s triangles added to `mesh`.
void append(Mesh& mesh, const Mesh& part)
{
    const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
    mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
    for (const std::uint32_t index : part.indices)
        mesh.indices.push_back(index + offset);
}

// A rotation keeps the triangles' turn, so normals turn with the positions.
Mesh rotated(Mesh mesh, const Eigen::Quaternionf& rotation)
{
    for (Eigen::Vector3f& position : mesh.positions)
        position = rotation * position;
    for (Eigen::Vector3f& normal : mesh.normals)
        normal = rotation * normal;
    return mesh;
}

// A top standing on its tip at the origin, its stem up the z axis.
std::shared_ptr<const Mesh> topMesh()
{
    return std::make_shared<const Mesh>(latheMesh(
        {{0.0f, 0.0f}, {0.55f, 0.55f}, {0.7f, 0.75f}, {0.55f, 0.9f}, {0.1f, 0.95f}, {0.1f, 1.35f}, {0.0f, 1.35f}},
        48));
}

// A block letter M, 1.5 tall and wide, 0.3 deep, standing in the xz plane and centred on the origin:
// two upright legs and two diagonals meeting below the middle, each a convex prism.
std::shared_ptr<const Mesh> letterMMesh()
{
    const std::vector<Eigen::Vector2f> leftLeg{{-0.75f, -0.75f}, {-0.5f, -0.75f}, {-0.5f, 0.75f}, {-0.75f, 0.75f}};
    const std::vector<Eigen::Vector2f> leftDiagonal{{-0.75f, 0.45f}, {0.0f, -0.3f}, {0.0f, 0.05f}, {-0.75f, 0.75f}};
    // Mirrored in x, each outline is walked backwards to stay counter-clockwise.
    const auto mirrored = [](const std::vector<Eigen::Vector2f>& outline) {
        std::vector<Eigen::Vector2f> mirror;
        for (auto point = outline.rbegin(); point != outline.rend(); ++point)
            mirror.emplace_back(-point->x(), point->y());
        return mirror;
    };
    Mesh letter;
    for (const auto& outline : {leftLeg, leftDiagonal, mirrored(leftLeg), mirrored(leftDiagonal)})
        append(letter, prismMesh(outline, 0.3f));
    // Standing up: the outline's y becomes z.
    return std::make_shared<const Mesh>(
        rotated(letter, Eigen::Quaternionf(Eigen::AngleAxisf(std::numbers::pi_v<float> / 2, Eigen::Vector3f::UnitX()))));
}

// A hat upright on the origin: a brim 1.1 across and a crown 0.65 high.
std::shared_ptr<const Mesh> hatMesh()
{
    return std::make_shared<const Mesh>(latheMesh(
        {{0.0f, 0.0f}, {0.55f, 0.0f}, {0.55f, 0.04f}, {0.3f, 0.06f}, {0.28f, 0.6f}, {0.2f, 0.65f}, {0.0f, 0.65f}}, 48));
}

// A leaf 1.0 long and 0.5 wide in the xy plane, 0.03 thick: pointed at both ends.
std::shared_ptr<const Mesh> leafMesh()
{
    constexpr int kOutlinePoints = 24;
    std::vector<Eigen::Vector2f> outline;
    for (int i = 0; i < kOutlinePoints; ++i) {
        const float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / kOutlinePoints;
        // (x, y) = (0.5·cos θ, 0.25·sin θ·|sin θ|): two parabolas y = ±0.25·(1 − 4x²) meeting in
        // points at the ends, a convex outline.
        const float sine = std::sin(angle);
        outline.emplace_back(0.5f * std::cos(angle), 0.25f * sine * std::abs(sine));
    }
    return std::make_shared<const Mesh>(prismMesh(outline, 0.03f));
}

// A pen 1.2 long along z, 0.1 across, its conical tip at the origin.
std::shared_ptr<const Mesh> penMesh()
{
    return std::make_shared<const Mesh>(
        latheMesh({{0.0f, 0.0f}, {0.05f, 0.15f}, {0.05f, 1.2f}, {0.0f, 1.2f}}, 24));
}

// A pendulum hanging from the origin: a rod 0.9 long and a bob below it.
std::shared_ptr<const Mesh> pendulumMesh()
{
    return std::make_shared<const Mesh>(latheMesh({{0.0f, -1.3f},
                                                   {0.2f, -1.25f},
                                                   {0.27f, -1.1f},
                                                   {0.2f, -0.95f},
                                                   {0.03f, -0.9f},
                                                   {0.03f, 0.0f},
                                                   {0.0f, 0.0f}},
                                                  24));
}

// A block 1.2 × 0.6 × 0.4 centred on the origin.
std::shared_ptr<const Mesh> blockMesh()
{
    return std::make_shared<const Mesh>(prismMesh({{-0.6f, -0.3f}, {0.6f, -0.3f}, {0.6f, 0.3f}, {-0.6f, 0.3f}}, 0.4f));
}

// A seated animal-ish figure on the origin: a round body 1.0 across and a head 0.7 across on it.
std::shared_ptr<const Mesh> critterMesh()
{
    constexpr int kArcPoints = 12;
    std::vector<Eigen::Vector2f> profile;
    // Arcs (r, z) = (R sin φ, c + R cos φ) from φ = from down to φ = to, bottom to top.
    const auto arc = [&profile](float radius, float centre, float from, float to) {
        for (int i = 0; i <= kArcPoints; ++i) {
            const float phi = from + (to - from) * static_cast<float>(i) / kArcPoints;
            profile.emplace_back(radius * std::sin(phi), centre + radius * std::cos(phi));
        }
    };
    arc(0.5f, 0.5f, std::numbers::pi_v<float>, 0.5f);  // the body, up to a neck 0.24 across
    arc(0.35f, 1.25f, 2.386f, 0.0f);                   // the head, from that neck (0.35·sin 2.386 ≈ 0.24)
    return std::make_shared<const Mesh>(latheMesh(profile, 32));
}

// Two spins at constant rates, one carried by the other:
//   q(t) = R(a, Ωₐt)·B·R(b, Ω_b t),   ω(t) = Ωₐ·a + Ω_b·R(a, Ωₐt)·B·b.
struct CarriedSpin {
    Eigen::Vector3d outerAxis = Eigen::Vector3d::UnitZ();
    double outerRate = 0.0;
    Eigen::Quaterniond between = Eigen::Quaterniond::Identity();
    Eigen::Vector3d innerAxis = Eigen::Vector3d::UnitZ();
    double innerRate = 0.0;

    Eigen::Quaterniond rotation(double t) const
    {
        return Eigen::Quaterniond(Eigen::AngleAxisd(outerRate * t, outerAxis) * between *
                                  Eigen::AngleAxisd(innerRate * t, innerAxis));
    }

    Eigen::Vector3d angularVelocity(double t) const
    {
        const Eigen::Vector3d axis = Eigen::AngleAxisd(outerRate * t, outerAxis) * (between * innerAxis);
        return outerRate * outerAxis + innerRate * axis;
    }
};

// A top precessing about z at Ωₚ = 1.5, tilted by θ₀ = 0.35, spinning about its own axis at Ωₛ = 9.
CarriedSpin steadyTop()
{
    return {Eigen::Vector3d::UnitZ(), 1.5, Eigen::Quaterniond(Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitX())),
            Eigen::Vector3d::UnitZ(), 9.0};
}

// One period of a sine, the wobble the artist draws once.
std::vector<Eigen::Vector2d> sineWiggle()
{
    constexpr int kPoints = 17;
    std::vector<Eigen::Vector2d> pattern;
    for (int i = 0; i < kPoints; ++i) {
        const double u = static_cast<double>(i) / (kPoints - 1);
        pattern.emplace_back(u, 0.375 * std::sin(2.0 * std::numbers::pi * u));
    }
    return pattern;
}

// How a sketch-paper sample is keyed (its Table 1 counts at 30 fps).
struct KeySchedule {
    int frames = 0;
    int framesPerKey = 1;
    int constrainedEvery = 1;  // a constrained key every this many keys; the fit moves the others
};

constexpr double kFps = 30.0;

// Keys of `spin` every framesPerKey frames up to the last frame, at `position(time)`.
model::MotionTrack keyedTrack(const CarriedSpin& spin, const std::function<Eigen::Vector3d(double)>& position,
                              const KeySchedule& schedule)
{
    model::MotionTrack track;
    track.interpolation = InterpolationMethod::Hermite;
    for (int key = 0; key * schedule.framesPerKey <= schedule.frames; ++key) {
        const double time = key * schedule.framesPerKey / kFps;
        track.keys.push_back(
            Keyframe{time, {spin.rotation(time), position(time)}, key % schedule.constrainedEvery == 0});
    }
    return track;
}

constexpr int kStrokePoints = 101;

// The time of point i of kStrokePoints spread over [start, end].
double strokeTime(double start, double end, int i)
{
    return start + (end - start) * i / (kStrokePoints - 1);
}

// A stroke over [start, end] tracing the spin axis of `spin`, as an artist draws over the curve the
// sphere shows, turned about `bendAxis` by bend(u) radians, u running 0 → 1 over the stroke.
model::DirectionStroke bentAxisStroke(const CarriedSpin& spin, double start, double end,
                                      const Eigen::Vector3d& bendAxis, const std::function<double(double)>& bend)
{
    model::DirectionStroke stroke;
    for (int i = 0; i < kStrokePoints; ++i) {
        const double time = strokeTime(start, end, i);
        const double u = static_cast<double>(i) / (kStrokePoints - 1);
        stroke.points.push_back(Eigen::AngleAxisd(bend(u), bendAxis) * spin.angularVelocity(time).normalized());
        stroke.times.push_back(time);
    }
    return stroke;
}

// A magnitude curve over [start, end]: |ω| of `spin` times scale(u), u running 0 → 1.
std::vector<model::MagnitudePoint> scaledMagnitude(const CarriedSpin& spin, double start, double end,
                                                   const std::function<double(double)>& scale)
{
    constexpr int kPoints = 41;
    std::vector<model::MagnitudePoint> curve;
    for (int i = 0; i < kPoints; ++i) {
        const double u = static_cast<double>(i) / (kPoints - 1);
        const double time = start + (end - start) * u;
        curve.push_back({time, spin.angularVelocity(time).norm() * scale(u)});
    }
    return curve;
}

// sin²(πu): 0 at both ends of the window, so the edit joins the untouched motion smoothly.
double bump(double u)
{
    const double s = std::sin(std::numbers::pi * u);
    return s * s;
}

// A scene of one object, its track keyed at 30 fps, lasting the schedule's frames.
SampleScene oneObjectScene(QString fileName, QString objectName, std::shared_ptr<const Mesh> mesh,
                           model::MotionTrack track, int frames)
{
    model::SceneObject object;
    object.id = 1;
    object.name = std::move(objectName);
    object.mesh = std::move(mesh);
    object.track = std::move(track);

    model::Scene scene;
    scene.objects.push_back(std::move(object));
    scene.fps = kFps;
    scene.startTime = 0.0;
    scene.endTime = frames / kFps;
    scene.nextObjectId = 2;
    return {std::move(fileName), std::move(scene)};
}

// A cyclic screw track through `poses`, one second apart (ScrewBender's polyscrew subdivision).
model::MotionTrack screwCycle(const std::vector<Pose>& poses, SubdivisionScheme scheme, int levels)
{
    model::MotionTrack track;
    track.interpolation = InterpolationMethod::Screw;
    track.subdivision = SubdivisionSettings{scheme, levels, true, false};
    for (std::size_t i = 0; i < poses.size(); ++i)
        track.keys.push_back(Keyframe{static_cast<double>(i), poses[i], true});
    return track;
}

// Two full cycles of a screw track with keys one second apart.
int twoCyclesOfFrames(const model::MotionTrack& track)
{
    return static_cast<int>(2 * track.keys.size() * kFps);
}

} // namespace

SampleScene spinningTop()
{
    constexpr KeySchedule kSchedule{420, 5, 12};  // 85 keys, a constrained one every 2 s
    constexpr double kStrokeStart = 2.0;
    constexpr double kStrokeEnd = 12.0;
    const CarriedSpin top = steadyTop();

    model::MotionTrack track = keyedTrack(top, [](double) { return Eigen::Vector3d::Zero(); }, kSchedule);
    // The stroke traces the top's own spin axis; the pattern then adds the wobble.
    track.sketch.directionStrokes.push_back(
        bentAxisStroke(top, kStrokeStart, kStrokeEnd, Eigen::Vector3d::UnitZ(), [](double) { return 0.0; }));
    track.sketch.pattern = sineWiggle();
    track.sketch.patternRepeat = 30;
    track.sketch.window = std::pair(kStrokeStart, kStrokeEnd); // converges at the default δ, 0.1 rad²/s
    return oneObjectScene(QStringLiteral("spinning-top.gyre"), QStringLiteral("Spinning top"), topMesh(),
                          std::move(track), kSchedule.frames);
}

SampleScene letterM()
{
    constexpr KeySchedule kSchedule{240, 5, 8};  // 49 keys, a constrained one every 1⅓ s
    constexpr double kStart = 1.5;
    constexpr double kEnd = 6.5;
    const CarriedSpin tumble{Eigen::Vector3d(0.3, 0.2, 1.0).normalized(), 0.6,
                             Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY())),
                             Eigen::Vector3d::UnitX(), 1.1};
    model::MotionTrack track = keyedTrack(tumble, [](double) { return Eigen::Vector3d(0.0, 0.0, 1.5); }, kSchedule);
    // Fig. 2: the axis swings one way and back the other along a curve of its own, and the letter
    // tumbles up to 60 % faster in the middle of the edit.
    track.sketch.directionStrokes.push_back(
        bentAxisStroke(tumble, kStart, kEnd, Eigen::Vector3d(1.0, -1.0, 0.5).normalized(),
                       [](double u) { return 0.6 * std::sin(2.0 * std::numbers::pi * u) * std::sin(std::numbers::pi * u); }));
    track.sketch.magnitude = scaledMagnitude(tumble, kStart, kEnd, [](double u) { return 1.0 + 0.6 * bump(u); });
    track.sketch.window = std::pair(kStart, kEnd);
    // The bent stroke leaves a fragment error of 0.114 rad²/s where the bend turns fastest, 0.046 s of
    // the target's mean squared speed: within the paper's δ = 0.1.
    return oneObjectScene(QStringLiteral("letter-m.gyre"), QStringLiteral("Letter M"), letterMMesh(), std::move(track),
                          kSchedule.frames);
}

SampleScene hat()
{
    constexpr KeySchedule kSchedule{240, 5, 8};  // 49 keys
    constexpr double kStart = 2.0;
    constexpr double kEnd = 6.0;
    // Two tosses of 4 s, a flip about x in each while the hat turns slowly about z.
    const CarriedSpin flip{Eigen::Vector3d::UnitZ(), 0.5, Eigen::Quaterniond::Identity(), Eigen::Vector3d::UnitX(),
                           std::numbers::pi / 2.0};
    const auto tossed = [](double time) {
        return Eigen::Vector3d(0.0, 0.0, 0.5 + 2.0 * std::abs(std::sin(std::numbers::pi * time / 4.0)));
    };
    model::MotionTrack track = keyedTrack(flip, tossed, kSchedule);
    // The second flip's axis leans 0.5 rad over, so the hat turns a cartwheel on its way.
    track.sketch.directionStrokes.push_back(
        bentAxisStroke(flip, kStart, kEnd, Eigen::Vector3d::UnitY(), [](double u) { return 0.5 * bump(u); }));
    track.sketch.window = std::pair(kStart, kEnd);
    return oneObjectScene(QStringLiteral("hat.gyre"), QStringLiteral("Hat"), hatMesh(), std::move(track),
                          kSchedule.frames);
}

SampleScene fallingLeaf()
{
    constexpr KeySchedule kSchedule{800, 10, 6};  // 81 keys, a constrained one every 2 s
    constexpr double kStart = 8.0;
    constexpr double kEnd = 16.0;
    const CarriedSpin tumble{Eigen::Vector3d::UnitZ(), 0.35,
                             Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX())),
                             Eigen::Vector3d::UnitX(), 0.5};
    // From 6 high to the ground in 26⅔ s, swaying 1.5 to the sides as it drifts along y.
    const auto falling = [](double time) {
        return Eigen::Vector3d(1.5 * std::sin(0.4 * time), 0.1 * time - 1.3, 6.0 - 0.21 * time);
    };
    model::MotionTrack track = keyedTrack(tumble, falling, kSchedule);
    // A gust: the leaf tumbles twice as fast about an axis rocking to and fro.
    track.sketch.directionStrokes.push_back(
        bentAxisStroke(tumble, kStart, kEnd, Eigen::Vector3d::UnitZ(),
                       [](double u) { return 0.5 * std::sin(4.0 * std::numbers::pi * u); }));
    track.sketch.magnitude = scaledMagnitude(tumble, kStart, kEnd, [](double u) { return 1.0 + bump(u); });
    track.sketch.window = std::pair(kStart, kEnd);
    return oneObjectScene(QStringLiteral("falling-leaf.gyre"), QStringLiteral("Leaf"), leafMesh(), std::move(track),
                          kSchedule.frames);
}

SampleScene pen()
{
    constexpr KeySchedule kSchedule{121, 5, 6};  // 25 keys up to frame 120, a constrained one every second
    constexpr double kStart = 0.5;
    constexpr double kEnd = 3.5;
    // End over end about y while it spins about its own axis.
    const CarriedSpin spun{Eigen::Vector3d::UnitY(), 1.5 * std::numbers::pi, Eigen::Quaterniond::Identity(),
                           Eigen::Vector3d::UnitZ(), 3.0};
    // Tossed from 0.5 up to 2.5 and caught again at 4 s: z = 0.5 + 2·t(4 − t)/4.
    const auto tossed = [](double time) { return Eigen::Vector3d(0.0, 0.0, 0.5 + 0.5 * time * (4.0 - time)); };
    model::MotionTrack track = keyedTrack(spun, tossed, kSchedule);
    // Only the speed is sketched: the pen whirls half as fast again at the top of the toss.
    track.sketch.magnitude = scaledMagnitude(spun, kStart, kEnd, [](double u) { return 1.0 + 0.5 * bump(u); });
    track.sketch.window = std::pair(kStart, kEnd);
    // Fragment errors grow with |ω|², and the pen whirls at up to 22 rad/s: the fit ends at 0.7 rad²/s,
    // 0.014 s of the target's mean squared speed, an angular-velocity error of a few per cent.
    return oneObjectScene(QStringLiteral("pen.gyre"), QStringLiteral("Pen"), penMesh(), std::move(track),
                          kSchedule.frames);
}

SampleScene pendulum()
{
    // ScrewBender's Fig. 7, left: two poses 80° apart about the pivot, 4-point subdivided into a swing.
    const Eigen::Vector3d pivot(0.0, 0.0, 2.0);
    const auto swungBy = [&pivot](double angle) {
        return Pose{Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX())), pivot};
    };
    model::MotionTrack track = screwCycle({swungBy(0.7), swungBy(-0.7)}, SubdivisionScheme::FourPoint, 5);
    const int frames = twoCyclesOfFrames(track);
    return oneObjectScene(QStringLiteral("pendulum.gyre"), QStringLiteral("Pendulum"), pendulumMesh(),
                          std::move(track), frames);
}

SampleScene spinningBlock()
{
    // ScrewBender's Fig. 7, right: four poses a quarter turn apart round a circle, each turned a further
    // quarter about a leaning axis, B-spline subdivided into a smooth spin.
    const Eigen::Vector3d leaningAxis = Eigen::Vector3d(0.0, 0.5, 1.0).normalized();
    std::vector<Pose> poses;
    for (int k = 0; k < 4; ++k) {
        const double angle = k * std::numbers::pi / 2.0;
        poses.push_back({Eigen::Quaterniond(Eigen::AngleAxisd(angle, leaningAxis)),
                         Eigen::Vector3d(1.5 * std::cos(angle), 1.5 * std::sin(angle), 1.0)});
    }
    model::MotionTrack track = screwCycle(poses, SubdivisionScheme::BSpline, 4);
    const int frames = twoCyclesOfFrames(track);
    return oneObjectScene(QStringLiteral("spinning-block.gyre"), QStringLiteral("Block"), blockMesh(),
                          std::move(track), frames);
}

SampleScene critterCycle()
{
    // ScrewBender's Fig. 12: six poses round a circle, rising and dipping in turn and leaning into the
    // turn, so the cycle leaves the plane; 4-point subdivision makes the path smooth.
    std::vector<Pose> poses;
    for (int k = 0; k < 6; ++k) {
        const double angle = k * std::numbers::pi / 3.0;
        const double lean = (k % 2 == 0) ? 0.3 : -0.3;
        const Eigen::Quaterniond heading(Eigen::AngleAxisd(angle + std::numbers::pi / 2.0, Eigen::Vector3d::UnitZ()));
        poses.push_back({heading * Eigen::AngleAxisd(lean, Eigen::Vector3d::UnitY()),
                         Eigen::Vector3d(2.0 * std::cos(angle), 2.0 * std::sin(angle), (k % 2 == 0) ? 0.2 : 1.2)});
    }
    model::MotionTrack track = screwCycle(poses, SubdivisionScheme::FourPoint, 4);
    const int frames = twoCyclesOfFrames(track);
    return oneObjectScene(QStringLiteral("critter-cycle.gyre"), QStringLiteral("Critter"), critterMesh(),
                          std::move(track), frames);
}

SampleScene withFitApplied(SampleScene sample)
{
    model::MotionTrack& track = sample.scene.objects.front().track;
    const model::SketchFitProblem problem = model::sketchFitProblem(track, model::flightBodyOf(sample.scene.objects.front()));
    const fit::FitResult result = model::fitSketch(problem);
    if (result.outcome != fit::FitOutcome::Converged)
        throw std::runtime_error(sample.fileName.toStdString() + ": the sketch's fit does not converge");
    model::FitResult applied = model::appliedFitResult(track, result);
    track = model::withFitApplied(std::move(track), std::move(applied));
    return sample;
}

std::vector<SampleScene> sketchedSamples()
{
    std::vector<SampleScene> samples;
    samples.push_back(spinningTop());
    samples.push_back(letterM());
    samples.push_back(hat());
    samples.push_back(fallingLeaf());
    samples.push_back(pen());
    return samples;
}

std::vector<SampleScene> allSamples()
{
    std::vector<SampleScene> samples;
    for (SampleScene& sketched : sketchedSamples())
        samples.push_back(withFitApplied(std::move(sketched)));
    samples.push_back(pendulum());
    samples.push_back(spinningBlock());
    samples.push_back(critterCycle());
    return samples;
}

} // namespace gyre::samples
