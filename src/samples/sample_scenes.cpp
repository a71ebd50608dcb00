#include "samples/sample_scenes.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>

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

// A top standing on its tip at the origin, its stem up the z axis.
std::shared_ptr<const Mesh> topMesh()
{
    return std::make_shared<const Mesh>(latheMesh(
        {{0.0f, 0.0f}, {0.55f, 0.55f}, {0.7f, 0.75f}, {0.55f, 0.9f}, {0.1f, 0.95f}, {0.1f, 1.35f}, {0.0f, 1.35f}},
        48));
}

// A top precessing about z at Ωₚ, tilted by θ₀, spinning about its own axis at Ωₛ:
//   q(t) = Rz(Ωₚt)·Rx(θ₀)·Rz(Ωₛt),   ω(t) = Ωₚ·ẑ + Ωₛ·Rz(Ωₚt)·Rx(θ₀)·ẑ.
struct SteadyTop {
    double precession = 1.5;
    double tilt = 0.35;
    double spin = 9.0;

    Eigen::Quaterniond rotation(double t) const
    {
        return Eigen::Quaterniond(Eigen::AngleAxisd(precession * t, Eigen::Vector3d::UnitZ()) *
                                  Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()) *
                                  Eigen::AngleAxisd(spin * t, Eigen::Vector3d::UnitZ()));
    }

    Eigen::Vector3d angularVelocity(double t) const
    {
        const Eigen::Vector3d axis = Eigen::AngleAxisd(precession * t, Eigen::Vector3d::UnitZ()) *
                                     (Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitZ());
        return precession * Eigen::Vector3d::UnitZ() + spin * axis;
    }
};

// One period of a sine, the wobble the artist draws once.
std::vector<Eigen::Vector2d> sineWiggle()
{
    constexpr int kPoints = 17;
    std::vector<Eigen::Vector2d> pattern;
    for (int i = 0; i < kPoints; ++i) {
        const double u = static_cast<double>(i) / (kPoints - 1);
        pattern.emplace_back(u, 0.25 * std::sin(2.0 * std::numbers::pi * u));
    }
    return pattern;
}

} // namespace

SampleScene spinningTop()
{
    constexpr double kFps = 30.0;
    constexpr int kFrames = 420;
    constexpr int kFramesPerKey = 5;            // 85 keys
    constexpr int kConstrainedEvery = 12;       // a constrained key every 2 s; the fit moves the others
    constexpr double kStrokeStart = 2.0;
    constexpr double kStrokeEnd = 12.0;
    constexpr int kStrokePoints = 101;
    const SteadyTop top;

    model::SceneObject object;
    object.id = 1;
    object.name = QStringLiteral("Spinning top");
    object.mesh = topMesh();
    model::MotionTrack& track = object.track;
    track.interpolation = InterpolationMethod::Hermite;
    for (int key = 0; key * kFramesPerKey <= kFrames; ++key) {
        const double time = key * kFramesPerKey / kFps;
        track.keys.push_back(Keyframe{time, {top.rotation(time), Eigen::Vector3d::Zero()}, key % kConstrainedEvery == 0});
    }

    // The stroke traces the top's own spin axis, as an artist draws over the curve the sphere shows;
    // the pattern then adds the wobble.
    model::DirectionStroke stroke;
    for (int i = 0; i < kStrokePoints; ++i) {
        const double time = kStrokeStart + (kStrokeEnd - kStrokeStart) * i / (kStrokePoints - 1);
        stroke.points.push_back(top.angularVelocity(time).normalized());
        stroke.times.push_back(time);
    }
    track.sketch.directionStrokes.push_back(std::move(stroke));
    track.sketch.pattern = sineWiggle();
    track.sketch.patternRepeat = 30;
    track.sketch.window = std::pair(kStrokeStart, kStrokeEnd);
    // At the default δ = 0.1 rad²/s the fit stops at a fragment error of 0.1002, "no place for a
    // variable frame", which reads like a failure; at 0.15 it converges in two rounds (0.118).
    track.sketch.delta = 0.15;

    model::Scene scene;
    scene.objects.push_back(std::move(object));
    scene.fps = kFps;
    scene.startTime = 0.0;
    scene.endTime = kFrames / kFps;
    scene.nextObjectId = 2;
    return {QStringLiteral("spinning-top.gyre"), std::move(scene)};
}

std::vector<SampleScene> allSamples()
{
    std::vector<SampleScene> samples;
    samples.push_back(spinningTop());
    return samples;
}

} // namespace gyre::samples
