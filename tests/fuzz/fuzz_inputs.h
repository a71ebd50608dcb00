#pragma once
// What the fuzz tests feed Gyre's readers, shared by the mutation tests (tst_fuzz_readers,
// tst_fuzz_scene_files) and the libFuzzer harnesses (fuzz_pose_csv, fuzz_project): valid seed files
// made in code, and one run of a reader on given bytes with the checks every input must pass.
//
// The readers read files by path, so each input is written to a file first; the file's path is the
// name every refusal message must carry.

#include "model/scene.h"

#include <QByteArray>
#include <QString>

#include <optional>
#include <string>
#include <vector>

namespace gyre::fuzz {

enum class Reader {
    PoseCsv,   // io::readPoseCsv, Euler angles in the default convention
    NumberCsv, // io::readNumberCsv with the columns of an angular-velocity file: time,wx,wy,wz
    Project,   // readProject, then every track evaluated
    Scene,     // io::importSceneInWorker (Assimp in gyre-scene-worker), then every track evaluated
};

struct Seed {
    QString name; // a file name, unique among the seeds
    Reader reader;
    QByteArray bytes;
};

// Valid files of every kind: pose CSV files of each rotation column set, number files, and project
// files with sketch state, a fitted curve, a shared mesh, a screw track. `scratchDir` is an existing
// directory for the files the writers make on the way.
std::vector<Seed> makeSeeds(const QString& scratchDir);

// Valid scene files, one of each format Gyre writes that keeps its motion in one file (glb, Collada,
// binary FBX) and OBJ, written by Gyre's exporters from a scene with a parent, a shared mesh and
// keys, and a BVH motion capture written by hand. Scene readers are Assimp's, so these are read
// through gyre-scene-worker, which must be found (io/scene_worker.h).
std::vector<Seed> makeSceneSeeds(const QString& scratchDir);

// What one input came to. Anything thrown other than the reader's InputError, and TrackMotion's
// documented std::invalid_argument, leaves readInput.
struct Outcome {
    bool accepted = false;
    std::string refusal; // the InputError's message when refused
    int tracksEvaluated = 0;
    int tracksRefusedByEvaluation = 0; // TrackMotion's std::invalid_argument, e.g. a subdivision too large
    // What is wrong with the first pose or angular velocity of an accepted scene that is not finite.
    std::optional<std::string> evaluationProblem;
};

// Writes `bytes` to `path` and runs `reader` on it. For an accepted project or scene, evaluates each
// track at its key times, the scene's range and current time and points between and beyond: pose and
// angular velocity. A scene file's worker may crash or hang on it: that is a refusal naming the file
// (scene_worker.h), and the reason the scene readers run in a worker.
Outcome readInput(Reader reader, const QByteArray& bytes, const QString& path);

// What is wrong with a refusal message for the file at `path`, or nothing: the message must begin
// with the path, then a line number (CSV files) or, for a project, a field, the top level, or the byte
// where the JSON breaks; for a scene file, what went wrong.
std::optional<std::string> refusalProblem(Reader reader, const std::string& message, const QString& path);

} // namespace gyre::fuzz
