// gyre-bench: the speed figures of the motion core. Run a Release build on an idle machine:
//   build/tests/bench/gyre-bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Targets on one core: a screw under 35 ns, Jarek to 5 levels on 64 poses under 0.5 ms, the
// angular-velocity fit under 30 ms for 20 keys and under 200 ms for the paper's Top (85 keys).

#include "core/euler_angles.h"
#include "core/orientation_curves.h"
#include "core/quaternion_math.h"
#include "core/screw.h"
#include "core/screw_batch.h"
#include "core/subdivision.h"
#include "core/torque_free.h"
#include "fit/angular_velocity_fit.h"
#include "fit/flight_shooting.h"
#include "model/sketch_fit_problem.h"
#include "samples/sample_scenes.h"
#include "fit_test_support.h"
#include "core/core_test_support.h"

#include "io/bvh_fixture.h"
#include "io/scene_export.h"
#include "io/scene_import.h"
#include "model/project_file.h"
#include "model/scene.h"
#include "model/scene_motion.h"
#include "model/skinning.h"
#include "io/scene_wire.h"
#include "io/scene_worker.h"
#include "built_scene_worker.h"

#include <benchmark/benchmark.h>

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <span>
#include <stdexcept>
#include <vector>

namespace {

using gyre::Pose;

constexpr std::size_t kPairs = 1024; // a power of two, so the index wraps with a mask

Eigen::Quaterniond randomRotation(std::mt19937_64& rng)
{
    std::normal_distribution<double> normal;
    return Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
}

Pose randomPose(std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
    return {randomRotation(rng), {coordinate(rng), coordinate(rng), coordinate(rng)}};
}

struct PosePairs {
    std::vector<Pose> from;
    std::vector<Pose> to;
    std::vector<double> t;
};

PosePairs randomPairs()
{
    std::mt19937_64 rng(20261121);
    std::uniform_real_distribution<double> fraction(-0.25, 1.25);
    PosePairs pairs;
    for (std::size_t i = 0; i < kPairs; ++i) {
        pairs.from.push_back(randomPose(rng));
        pairs.to.push_back(randomPose(rng));
        pairs.t.push_back(fraction(rng));
    }
    return pairs;
}

// 64 control poses on a wobbling loop: each turns a little further about a tilting axis.
std::vector<Pose> cyclicControlPoses(std::size_t count)
{
    std::vector<Pose> poses;
    for (std::size_t i = 0; i < count; ++i) {
        const double phase = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(count);
        const Eigen::Vector3d axis(std::cos(3.0 * phase), std::sin(3.0 * phase), 2.0);
        const Eigen::Quaterniond orientation(Eigen::AngleAxisd(phase, axis.normalized()));
        poses.push_back({orientation, {3.0 * std::cos(phase), 2.0 * std::sin(phase), std::sin(2.0 * phase)}});
    }
    return poses;
}

// One iteration computes exactly one s(La, t, Lb), screw parameters included, for a pair that
// changes from one iteration to the next.
void BM_Screw(benchmark::State& state)
{
    const PosePairs pairs = randomPairs();
    std::size_t i = 0;
    for (auto _ : state) {
        Pose pose = gyre::screwInterpolate(pairs.from[i], pairs.t[i], pairs.to[i]);
        benchmark::DoNotOptimize(pose);
        i = (i + 1) & (kPairs - 1);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Screw);

// BM_Screw's work on all kPairs pairs at once (screw_batch.h): every screw built and evaluated at one
// t, which changes from one iteration to the next. Per screw: items are screws. The poses are in
// PoseBuffers, as the subdivision holds them.
template <class Batch>
void screwBatchBenchmark(benchmark::State& state, Batch batch)
{
    const PosePairs pairs = randomPairs();
    const gyre::PoseBuffer from(pairs.from.begin(), pairs.from.end());
    const gyre::PoseBuffer to(pairs.to.begin(), pairs.to.end());
    gyre::PoseBuffer out(kPairs);
    std::size_t i = 0;
    for (auto _ : state) {
        batch(from, to, std::span(&pairs.t[i], 1), out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
        i = (i + 1) & (kPairs - 1);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kPairs));
}

// The version this processor runs: the widest lanes it has (AVX-512's, AVX2's or SSE2's).
void BM_ScrewBatch(benchmark::State& state)
{
    screwBatchBenchmark(state, gyre::screwsAt);
}
BENCHMARK(BM_ScrewBatch);

// Each narrower version, which a processor without the wider instructions runs; skipped on one
// without its own.
template <gyre::screw_batch_detail::InstructionSet set>
void screwBatchWithBenchmark(benchmark::State& state)
{
    if (!gyre::screw_batch_detail::processorHas(set)) {
        state.SkipWithError("this processor lacks the instructions of these lanes");
        return;
    }
    screwBatchBenchmark(state, [](std::span<const Pose> from, std::span<const Pose> to, std::span<const double> times,
                                  std::span<Pose> out) { gyre::screw_batch_detail::screwsAtWith(set, from, to, times, out); });
}

// Four doubles a register (AVX2).
void BM_ScrewBatchAvx2(benchmark::State& state)
{
    screwBatchWithBenchmark<gyre::screw_batch_detail::InstructionSet::Avx2>(state);
}
BENCHMARK(BM_ScrewBatchAvx2);

// Two doubles a register (SSE2), which every x86-64 processor has.
void BM_ScrewBatchPortable(benchmark::State& state)
{
    screwBatchWithBenchmark<gyre::screw_batch_detail::InstructionSet::Sse2>(state);
}
BENCHMARK(BM_ScrewBatchPortable);

// The screw of one pair computed once, then evaluated at a different t every iteration.
void BM_ScrewEvaluate(benchmark::State& state)
{
    const PosePairs pairs = randomPairs();
    const gyre::Screw screw(pairs.from[0], pairs.to[0]);
    std::size_t i = 0;
    for (auto _ : state) {
        Pose pose = screw.at(pairs.t[i]);
        benchmark::DoNotOptimize(pose);
        i = (i + 1) & (kPairs - 1);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ScrewEvaluate);

// The screw as an Eigen program would write it, the SE(3) geodesic La·exp(t·log(La⁻¹Lb)) with 4×4
// matrices (tests/core/core_test_support.h, the tests' independent construction): BM_Screw's Eigen row.
// BM_Screw's floors (README): its 95 multiplies, 65 additions, square root and division, on two
// multiply pipes that the square root and division share for ~12.5 cycles: ~54 cycles, 15 ns at
// 3.6 GHz, one screw at a time; 7.5 ns a screw with SSE2's two lanes, 3.7 ns with AVX2's four (4.0
// with AVX-512's eight, whose square root and division hold the pipes longer here).
void BM_ScrewEigen(benchmark::State& state)
{
    const PosePairs pairs = randomPairs();
    std::size_t i = 0;
    for (auto _ : state) {
        Eigen::Matrix4d pose = gyre::test::geodesic(pairs.from[i], pairs.to[i], pairs.t[i]);
        benchmark::DoNotOptimize(pose);
        i = (i + 1) & (kPairs - 1);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ScrewEigen);

// Each core operation has an Eigen row right after it, on the same inputs, so that every run prints
// the ratio: gyre's time over the *Eigen row's.
void BM_Slerp(benchmark::State& state)
{
    const PosePairs pairs = randomPairs();
    std::size_t i = 0;
    for (auto _ : state) {
        Eigen::Quaterniond q = gyre::slerp(pairs.from[i].orientation, pairs.to[i].orientation, pairs.t[i]);
        benchmark::DoNotOptimize(q);
        i = (i + 1) & (kPairs - 1);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Slerp);

// Eigen's Quaterniond::slerp, which also takes the short arc.
void BM_SlerpEigen(benchmark::State& state)
{
    const PosePairs pairs = randomPairs();
    std::size_t i = 0;
    for (auto _ : state) {
        Eigen::Quaterniond q = pairs.from[i].orientation.slerp(pairs.t[i], pairs.to[i].orientation);
        benchmark::DoNotOptimize(q);
        i = (i + 1) & (kPairs - 1);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SlerpEigen);

// The 12 orders, intrinsic (Eigen's eulerAngles convention), taken in turn: one order per iteration.
const std::vector<gyre::EulerConvention>& intrinsicOrders()
{
    static const std::vector<gyre::EulerConvention> orders = [] {
        std::vector<gyre::EulerConvention> intrinsic;
        for (const gyre::EulerConvention& convention : gyre::EulerConvention::all())
            if (convention.frame == gyre::AngleFrame::Intrinsic)
                intrinsic.push_back(convention);
        return intrinsic;
    }();
    return orders;
}

std::size_t nextOrder(std::size_t order)
{
    return order + 1 == intrinsicOrders().size() ? 0 : order + 1;
}

void BM_EulerAnglesFromQuaternion(benchmark::State& state)
{
    const PosePairs pairs = randomPairs();
    const std::vector<gyre::EulerConvention>& orders = intrinsicOrders();
    std::size_t i = 0;
    std::size_t order = 0;
    for (auto _ : state) {
        gyre::EulerAngles angles = gyre::eulerAnglesFromQuaternion(pairs.from[i].orientation, orders[order]);
        benchmark::DoNotOptimize(angles);
        i = (i + 1) & (kPairs - 1);
        order = nextOrder(order);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EulerAnglesFromQuaternion);

// Eigen 3.4 has no canonicalEulerAngles: toRotationMatrix().eulerAngles(i, j, k), the intrinsic angles
// (first in [0, π]; no gimbal-lock distance).
void BM_EulerAnglesFromQuaternionEigen(benchmark::State& state)
{
    const PosePairs pairs = randomPairs();
    const std::vector<gyre::EulerConvention>& orders = intrinsicOrders();
    std::size_t i = 0;
    std::size_t order = 0;
    for (auto _ : state) {
        const auto& axes = orders[order].axes;
        Eigen::Vector3d angles = pairs.from[i].orientation.toRotationMatrix().eulerAngles(axes[0], axes[1], axes[2]);
        benchmark::DoNotOptimize(angles);
        i = (i + 1) & (kPairs - 1);
        order = nextOrder(order);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EulerAnglesFromQuaternionEigen);

// Random angle triples, uniform in [−π, π)³.
std::vector<Eigen::Vector3d> randomAngleTriples()
{
    std::mt19937_64 rng(20261126);
    std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
    std::vector<Eigen::Vector3d> triples;
    for (std::size_t i = 0; i < kPairs; ++i)
        triples.emplace_back(angle(rng), angle(rng), angle(rng));
    return triples;
}

void BM_QuaternionFromEulerAngles(benchmark::State& state)
{
    const std::vector<Eigen::Vector3d> triples = randomAngleTriples();
    const std::vector<gyre::EulerConvention>& orders = intrinsicOrders();
    std::size_t i = 0;
    std::size_t order = 0;
    for (auto _ : state) {
        Eigen::Quaterniond q = gyre::quaternionFromEulerAngles(triples[i], orders[order]);
        benchmark::DoNotOptimize(q);
        i = (i + 1) & (kPairs - 1);
        order = nextOrder(order);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_QuaternionFromEulerAngles);

// Eigen's way: the product of three AngleAxisd about unit axes.
void BM_QuaternionFromEulerAnglesEigen(benchmark::State& state)
{
    const std::vector<Eigen::Vector3d> triples = randomAngleTriples();
    const std::vector<gyre::EulerConvention>& orders = intrinsicOrders();
    std::size_t i = 0;
    std::size_t order = 0;
    for (auto _ : state) {
        const auto& axes = orders[order].axes;
        const Eigen::Vector3d& e = triples[i];
        Eigen::Quaterniond q = Eigen::AngleAxisd(e[0], Eigen::Vector3d::Unit(axes[0])) *
                               Eigen::AngleAxisd(e[1], Eigen::Vector3d::Unit(axes[1])) *
                               Eigen::AngleAxisd(e[2], Eigen::Vector3d::Unit(axes[2]));
        benchmark::DoNotOptimize(q);
        i = (i + 1) & (kPairs - 1);
        order = nextOrder(order);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_QuaternionFromEulerAnglesEigen);

// One sample (value, derivative, angular velocity) of a squad curve through 64 keys.
void BM_SquadSample(benchmark::State& state)
{
    std::vector<gyre::OrientationKey> keys;
    for (const Pose& pose : cyclicControlPoses(64))
        keys.push_back({static_cast<double>(keys.size()) / 24.0, pose.orientation});
    const gyre::SquadCurve curve(keys);
    const double end = curve.endTime();
    double t = 0.0;
    for (auto _ : state) {
        gyre::OrientationSample sample = curve.sample(t);
        benchmark::DoNotOptimize(sample);
        t += 0.01;
        if (t > end)
            t = 0.0;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SquadSample);

// Each scheme on 64 cyclic control poses to 5 levels (2048 poses), reusing the subdivider's buffers
// as the app does while a pose is dragged; `jarek_open`, the same poses as an open sequence, whose
// every level also makes a ghost pose past each end.
void BM_Subdivide(benchmark::State& state, gyre::SubdivisionScheme scheme, bool decoupled, bool cyclic = true)
{
    const std::vector<Pose> control = cyclicControlPoses(64);
    gyre::PolyscrewSubdivider subdivider;
    const gyre::SubdivisionSettings settings{scheme, 5, cyclic, decoupled};
    std::size_t posesMade = 0;
    for (auto _ : state) {
        const std::vector<Pose>& poses = subdivider.subdivide(control, settings);
        benchmark::DoNotOptimize(poses.data());
        posesMade = poses.size();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(posesMade));
}
BENCHMARK_CAPTURE(BM_Subdivide, four_point, gyre::SubdivisionScheme::FourPoint, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Subdivide, four_point_b, gyre::SubdivisionScheme::FourPointB, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Subdivide, bspline, gyre::SubdivisionScheme::BSpline, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Subdivide, jarek, gyre::SubdivisionScheme::Jarek, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Subdivide, jarek_decoupled, gyre::SubdivisionScheme::Jarek, true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Subdivide, jarek_open, gyre::SubdivisionScheme::Jarek, false, false)->Unit(benchmark::kMicrosecond);

// The sketch-editing paper's Top: keys every 5 frames at 24 fps of a top that only spins and precesses
// (the paper's "simple circular motion"), and as the target the angular velocity of the same top
// nutating, the wobble the artist adds. 85 keys span 420 frames, as in the paper's Table 1.
void BM_Fit(benchmark::State& state)
{
    constexpr double kKeySpacing = 5.0 / 24.0;
    const auto keyCount = static_cast<std::size_t>(state.range(0));
    const double duration = static_cast<double>(keyCount - 1) * kKeySpacing;
    gyre::test::NutatingTop steady;
    steady.nutation = 0.0;
    const gyre::test::NutatingTop wobbling;
    const std::vector<gyre::fit::FitKey> keys = steady.keys(duration, kKeySpacing);
    const gyre::fit::AngularVelocityTarget target = wobbling.target(0.0, duration, 240.0);
    gyre::fit::FitResult result;
    for (auto _ : state) {
        result = gyre::fit::fitAngularVelocity(keys, target, gyre::fit::FitSettings{});
        benchmark::DoNotOptimize(result.controlPoints.data());
    }
    state.counters["rounds"] = result.rounds;
    state.counters["iterations"] = result.iterations;
    state.counters["variable_frames"] = result.variableFrames;
    state.counters["largest_F_n"] = result.largestFragmentError;
}
// 100 to 3000 keys show whether the fit's time grows linearly with the keys (µs a key = time / keys).
BENCHMARK(BM_Fit)->Arg(20)->Arg(85)->Arg(100)->Arg(400)->Arg(2000)->Arg(3000)->Unit(benchmark::kMillisecond);

// A free flight of one second between two keys of a T-handle-like body (principal moments 1 : 2 : 3, rotated
// off the body axes), the second key a little over a turn from the first: the shooting of every seed, the
// polish and the sort (flight_shooting.h). Target: a few milliseconds, so it can run while a key is dragged.
gyre::fit::FlightSpan benchFlightSpan()
{
    const Eigen::Quaterniond axes(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, 2.0, 0.5).normalized()));
    const Eigen::Matrix3d r = axes.toRotationMatrix();
    const Eigen::Matrix3d inertia = r * Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal() * r.transpose();
    const gyre::TorqueFreeMotion made(inertia, Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.5, 7.0, 0.3), 1.0);
    return {inertia, Eigen::Quaterniond::Identity(), made.orientation(1.0), 1.0};
}

// A span never solved before: solveFlight remembers the spans it solved, so each iteration turns the end key by
// another nanoradian, the same problem with other bits.
void BM_FlightSolve(benchmark::State& state)
{
    const gyre::fit::FlightSpan span = benchFlightSpan();
    std::vector<gyre::fit::FlightSolution> solutions;
    static int turned = 0;
    for (auto _ : state) {
        gyre::fit::FlightSpan fresh = span;
        fresh.end = span.end * Eigen::Quaterniond(Eigen::AngleAxisd(1e-9 * ++turned, Eigen::Vector3d::UnitX()));
        solutions = gyre::fit::solveFlight(fresh);
        benchmark::DoNotOptimize(solutions.data());
    }
    state.counters["solutions"] = static_cast<double>(solutions.size());
}
BENCHMARK(BM_FlightSolve)->Unit(benchmark::kMillisecond);

// The same span again with the artist's hint, as when a neighbouring key is dragged: the fixed seeds' solutions
// are remembered, the hint is solved.
void BM_FlightSolveRemembered(benchmark::State& state)
{
    const gyre::fit::FlightSpan span = benchFlightSpan();
    std::vector<gyre::fit::FlightSolution> solutions = gyre::fit::solveFlight(span);
    const Eigen::Vector3d hint = solutions.front().startAngularVelocity + Eigen::Vector3d(0.2, -0.1, 0.1);
    for (auto _ : state) {
        solutions = gyre::fit::solveFlight(span, hint);
        benchmark::DoNotOptimize(solutions.data());
    }
    state.counters["solutions"] = static_cast<double>(solutions.size());
}
BENCHMARK(BM_FlightSolveRemembered)->Unit(benchmark::kMillisecond);

// One sample of a built flight, as the viewport takes it every frame: orientation and angular velocity.
void BM_FlightEvaluate(benchmark::State& state)
{
    const gyre::fit::FlightSpan span = benchFlightSpan();
    const gyre::TorqueFreeMotion motion(span.inertia, span.start, gyre::fit::solveFlight(span).front().startAngularVelocity,
                                        span.duration);
    std::size_t i = 0;
    for (auto _ : state) {
        const double t = static_cast<double>(i++ % 997) / 997.0;
        benchmark::DoNotOptimize(motion.orientation(t));
        benchmark::DoNotOptimize(motion.angularVelocity(t));
    }
    state.counters["steps"] = static_cast<double>(motion.stepCount());
}
BENCHMARK(BM_FlightEvaluate);

// What the app's Fit button does on the bundled spinning top, between the click and the result: the
// sketch turned into the fit's problem, then the fit.
void BM_FitSpinningTopSample(benchmark::State& state)
{
    const gyre::model::MotionTrack track = gyre::samples::spinningTop().scene.objects.front().track;
    gyre::fit::FitResult result;
    for (auto _ : state) {
        const gyre::model::SketchFitProblem problem = gyre::model::sketchFitProblem(track, {});
        result = gyre::model::fitSketch(problem);
        benchmark::DoNotOptimize(result.controlPoints.data());
    }
    state.counters["rounds"] = result.rounds;
    state.counters["iterations"] = result.iterations;
    state.counters["variable_frames"] = result.variableFrames;
    state.counters["largest_F_n"] = result.largestFragmentError;
}
BENCHMARK(BM_FitSpinningTopSample)->Unit(benchmark::kMillisecond);

// A motion-capture file the size of CMU's 01_03.bvh: 31 joints, 4500 frames at 120 Hz, 139,500
// rotation keys. Written once, into a folder removed at exit. GYRE_BENCH_BVH names another file to
// use instead, such as one scripts/mocap-bvh.py writes.
const QString& largeBvh()
{
    static QTemporaryDir folder;
    static const QString path = [] {
        if (qEnvironmentVariableIsSet("GYRE_BENCH_BVH"))
            return qEnvironmentVariable("GYRE_BENCH_BVH");
        const QString file = folder.filePath(QStringLiteral("large.bvh"));
        QFile out(file);
        if (!out.open(QIODevice::WriteOnly) || out.write(gyre::test::bvhChain(31, 4500, 1.0 / 120.0)) < 0)
            throw std::runtime_error("cannot write the BVH fixture");
        return file;
    }();
    return path;
}

void BM_ImportBvh(benchmark::State& state)
{
    for (auto _ : state)
        benchmark::DoNotOptimize(gyre::io::importScene(largeBvh()));
}
BENCHMARK(BM_ImportBvh)->Unit(benchmark::kMillisecond);

// Assimp's own read of the same file with Gyre's settings: the floor of the import.
void BM_AssimpReadBvh(benchmark::State& state)
{
    for (auto _ : state)
        benchmark::DoNotOptimize(gyre::io::readWithAssimpOnly(largeBvh()));
}
BENCHMARK(BM_AssimpReadBvh)->Unit(benchmark::kMillisecond);

// The same import as the app and gyre-cli run it: in gyre-scene-worker, the scene sent back over a
// pipe and checked on arrival.
void BM_ImportBvhInWorker(benchmark::State& state)
{
    gyre::test::useBuiltSceneWorker();
    for (auto _ : state)
        benchmark::DoNotOptimize(gyre::io::importSceneInWorker(largeBvh()));
}
BENCHMARK(BM_ImportBvhInWorker)->Unit(benchmark::kMillisecond);

// The parts of the worker's cost that are not starting a process: the worker writing the imported
// capture as its reply, and the parent reading it back with every value checked.
void BM_EncodeImportReply(benchmark::State& state)
{
    const gyre::io::wire::Reply reply = gyre::io::importScene(largeBvh());
    for (auto _ : state)
        benchmark::DoNotOptimize(gyre::io::wire::encodeReply(reply));
}
BENCHMARK(BM_EncodeImportReply)->Unit(benchmark::kMillisecond);

void BM_DecodeImportReply(benchmark::State& state)
{
    const QByteArray bytes = gyre::io::wire::encodeReply(gyre::io::importScene(largeBvh()));
    state.counters["bytes"] = static_cast<double>(bytes.size());
    for (auto _ : state)
        benchmark::DoNotOptimize(gyre::io::wire::decodeReply(bytes));
}
BENCHMARK(BM_DecodeImportReply)->Unit(benchmark::kMillisecond);

// The imported motion baked at 120 fps (every key a frame) and written as glb.
void BM_ExportGlb(benchmark::State& state)
{
    const gyre::model::Scene scene = gyre::io::importScene(largeBvh()).scene;
    QTemporaryDir folder;
    const QString path = folder.filePath(QStringLiteral("large.glb"));
    for (auto _ : state)
        benchmark::DoNotOptimize(gyre::io::exportScene(scene, path, gyre::io::SceneFormat::Glb, 120.0));
}
BENCHMARK(BM_ExportGlb)->Unit(benchmark::kMillisecond);

// A capture made in code, as an imported BVH is: a chain of `joints` keyed at 120 Hz for `frames`
// frames, the root moving, each other joint at a fixed offset from its parent (31 joints for 4500
// frames is CMU's 01_03.bvh, for 72,000 a ten-minute take: 2.2 million keys).
gyre::model::Scene capture(std::int64_t joints, std::int64_t frames)
{
    std::mt19937_64 rng(20261125);
    gyre::model::Scene scene;
    for (gyre::model::ObjectId joint = 1; joint <= static_cast<gyre::model::ObjectId>(joints); ++joint) {
        gyre::model::SceneObject object;
        object.id = joint;
        object.parent = joint - 1;
        std::vector<gyre::model::Keyframe> keys(static_cast<std::size_t>(frames));
        for (std::size_t frame = 0; frame < keys.size(); ++frame) {
            const double time = static_cast<double>(frame) / 120.0;
            const Eigen::Vector3d offset = joint == 1 ? Eigen::Vector3d(0.25 * time, 0.0, 0.0) : Eigen::Vector3d(0, 2, 0);
            keys[frame] = {time, {randomRotation(rng), offset}, true};
        }
        object.track.keys = std::move(keys);
        scene.objects.push_back(std::move(object));
    }
    scene.nextObjectId = static_cast<gyre::model::ObjectId>(joints) + 1;
    scene.endTime = static_cast<double>(frames) / 120.0;
    return scene;
}

// What Autosave's tick costs the UI thread (jobs/autosave.h): the snapshot of the scene it hands to
// its worker, which writes the project there.
void BM_AutosaveSnapshot(benchmark::State& state)
{
    const gyre::model::Scene scene = capture(31, state.range(0));
    for (auto _ : state) {
        gyre::model::Scene snapshot = scene;
        benchmark::DoNotOptimize(snapshot);
    }
}
BENCHMARK(BM_AutosaveSnapshot)->Arg(4500)->Arg(72000)->Unit(benchmark::kMicrosecond);

// A project at scale saved, as Save and the autosave's worker do (every block checked, then
// written), and opened: 100 joints for `frames` frames, the capture of docs/file-format.md's cost.
void BM_SaveProject(benchmark::State& state)
{
    const gyre::model::Scene scene = capture(100, state.range(0));
    QTemporaryDir folder;
    const QString path = folder.filePath(QStringLiteral("capture.gyre"));
    for (auto _ : state)
        gyre::model::writeProject(path, scene);
    state.counters["bytes"] = static_cast<double>(QFileInfo(path).size());
}
BENCHMARK(BM_SaveProject)->Arg(6000)->Unit(benchmark::kMillisecond);

void BM_OpenProject(benchmark::State& state)
{
    QTemporaryDir folder;
    const QString path = folder.filePath(QStringLiteral("capture.gyre"));
    gyre::model::writeProject(path, capture(100, state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(gyre::model::readProject(path));
}
BENCHMARK(BM_OpenProject)->Arg(6000)->Unit(benchmark::kMillisecond);

// The per-frame work of a capture-sized skin before its upload: the 31 joint matrices of a chain,
// each joint's world pose composed up the chain from the shared motion (model/skinning.h).
void BM_JointMatrices31(benchmark::State& state)
{
    constexpr int kJoints = 31;
    gyre::model::Scene scene;
    gyre::model::Skin skin;
    for (int j = 0; j < kJoints; ++j) {
        const auto id = static_cast<gyre::model::ObjectId>(j + 1);
        gyre::model::SceneObject joint{id, QStringLiteral("Joint"), nullptr, j == 0 ? gyre::model::kNoObject : id - 1, {}, true};
        // Two keys, so that evaluating interpolates as playback does.
        joint.track.keys = {gyre::model::Keyframe{0.0, gyre::Pose{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.1, 0, 0)}, true},
                            gyre::model::Keyframe{1.0, gyre::Pose{Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ())),
                                                                  Eigen::Vector3d(0.1, 0, 0)}, true}};
        scene.objects.push_back(joint);
        skin.joints.push_back(id);
        skin.inverseBinds.push_back(Eigen::Matrix4f::Identity());
    }
    const gyre::model::SceneMotion motion(scene, [](const gyre::model::SceneObject& object) {
        return std::make_shared<const gyre::model::SharedTrackMotion>(object.track);
    });
    motion.build();
    double time = 0.0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(gyre::model::jointMatrices(skin, 1, motion, time));
        time = time < 1.0 ? time + 1.0 / 60.0 : 0.0;
    }
}
BENCHMARK(BM_JointMatrices31)->Unit(benchmark::kMicrosecond);

void BM_ExportGlbInWorker(benchmark::State& state)
{
    gyre::test::useBuiltSceneWorker();
    const gyre::model::Scene scene = gyre::io::importScene(largeBvh()).scene;
    QTemporaryDir folder;
    const QString path = folder.filePath(QStringLiteral("large.glb"));
    for (auto _ : state)
        benchmark::DoNotOptimize(gyre::io::exportSceneInWorker(scene, path, gyre::io::SceneFormat::Glb, 120.0));
}
BENCHMARK(BM_ExportGlbInWorker)->Unit(benchmark::kMillisecond);

// The same motion written as FBX through the worker, as the app and gyre-cli export it.
void BM_ExportFbxInWorker(benchmark::State& state)
{
    gyre::test::useBuiltSceneWorker();
    const gyre::model::Scene scene = gyre::io::importScene(largeBvh()).scene;
    QTemporaryDir folder;
    const QString path = folder.filePath(QStringLiteral("large.fbx"));
    for (auto _ : state)
        benchmark::DoNotOptimize(gyre::io::exportSceneInWorker(scene, path, gyre::io::SceneFormat::Fbx, 120.0));
    state.counters["bytes"] = static_cast<double>(QFileInfo(path).size());
}
BENCHMARK(BM_ExportFbxInWorker)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
