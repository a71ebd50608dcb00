#include "cli/help_text.h"

namespace gyre::cli {

namespace {

const char* const kGeneral = R"(Usage: gyre-cli VERB INPUT [-o OUTPUT] [options]

Batch verbs over pose CSV files (docs/pose-csv.md), projects (docs/file-format.md) and scene files
(docs/scene-files.md):
  convert      rewrite the rotation columns in another representation
  interpolate  sample a motion through timed keys at a frame rate
  subdivide    smooth a sequence of poses by polyscrew subdivision
  fit          bend the motion through keys to match a target angular velocity
  info         summarise a project or a scene file: objects, keyframes, time range (no -o)
  keys         write an object's keyframes from a project as a pose file
  bake         write an object's motion from a project at every frame as a pose file
  import       turn a scene file (FBX, glTF, Collada, BVH, OBJ, ...) into a project
  export       write a project as a scene file with its motion baked

  gyre-cli help VERB     usage of one verb (also: gyre-cli VERB --help)
  gyre-cli --version     the version

Options may come in any order. The output file appears only when the verb succeeds. `-o -` writes
to standard output (every verb but export); a FIFO or a device named by -o is written in place, never
replaced. An output may not name an input or another output (convert alone may rewrite its input).
A CSV input may hold at most 4194304 rows.
Exit status: 0 success, 1 bad input or output file, 2 bad command line.
)";

const char* const kCommonOptions = R"(
Options of every verb:
  -o, --output FILE  the output file, or - for standard output; only convert's may be the input
  --order AXES       axis order of Euler angle columns, e.g. xyz, zyx, zxz (default xyz);
                     e1 turns about the first axis named
  --intrinsic        angles about moving axes: intrinsic xyz is R = Rx(e1) Ry(e2) Rz(e3)
  --extrinsic        angles about fixed axes: extrinsic xyz is R = Rz(e3) Ry(e2) Rx(e1) (default)
)";

const char* const kConvert = R"(Usage: gyre-cli convert IN.csv -o OUT.csv --to SET [--order AXES] [--intrinsic|--extrinsic]

Rewrites the rotation columns of a pose file in another column set; time and position columns
pass through unchanged. The input may hold any one column set.

  --to SET   quat        qw,qx,qy,qz
             matrix      m00,m01,m02,m10,...,m22 (row-major, v' = M v)
             axis-angle  ax,ay,az,angle (angle in degrees)
             rotvec      rx,ry,rz (radians)
             euler       e1,e2,e3 (degrees; unwrapped along the file, no 360 degree jumps)

The Euler options say how to read Euler input and how to write Euler output. Rows within 1 degree
of gimbal lock are reported on standard error.)";

const char* const kInterpolate = R"(Usage: gyre-cli interpolate KEYS.csv -o FRAMES.csv --method METHOD --fps F [--order AXES] [--intrinsic|--extrinsic]
       gyre-cli interpolate KEYS.csv -o FRAMES.csv --method ballistic --inertia I --fps F [--solution K] [--gravity G] [--up X,Y,Z]

Samples the motion through timed keys (a time column is required, at least two keys) at
t0 + k/F up to the last key, plus a sample at every key time. Writes time,qw,qx,qy,qz,x,y,z.

  --method   slerp, nlerp, euler    orientation by that curve, position linear
             squad, hermite,        orientation by that curve, position cubic Hermite
             euler-cubic            (euler-cubic: each angle a cubic with automatic tangents)
             screw                  the polyscrew through the key poses
             ballistic              free flight between keys: torque-free rotation that meets
                                    each next key exactly, position on the parabola under gravity
  --fps F    samples per second, above 0 and at most 1000

Options of the ballistic method (the keys are the body's orientations, its origin its centre of mass):
  --inertia Ixx,Iyy,Izz[,Ixy,Ixz,Iyz]  the inertia tensor in the body frame (any unit; only ratios
                                       count), symmetric positive definite
  --solution K  the K-th solution of each span by kinetic energy, 0 the least (at most 6 per span);
                default: the one nearest the hermite motion's angular velocity at the span's start
  --gravity G   m/s^2, at least 0 (default 9.81)
  --up X,Y,Z    the world's up (default 0,0,1: Gyre is Z-up)

The Euler options say how to read Euler input, and the angles euler and euler-cubic interpolate: from
Euler columns the angles as read (0 then 360 is a full turn), from any other columns the orientations'
angles unwrapped along the keys (the Euler filter).)";

const char* const kSubdivide = R"(Usage: gyre-cli subdivide POSES.csv -o OUT.csv --scheme SCHEME --levels L [--open] [--decoupled] [--order AXES] [--intrinsic|--extrinsic]

Smooths a sequence of poses by ScrewBender's Split&Tweak subdivision. A cycle of n poses gives
n*2^L poses, an open sequence (n-1)*2^L+1; output pose i*2^L is the image of input pose i.
Times, where the input has them, are spread evenly within each input span; the span that closes a
cycle lasts the mean of the others. Writes time (if the input has it),qw,qx,qy,qz,x,y,z.

  --scheme     four-point, four-point-b, bspline or jarek
  --levels L   subdivision steps, each doubling the poses (at most 16777216 poses out)
  --open       an open sequence (default: a closed cycle)
  --decoupled  positions by the linear scheme and rotations separately, for comparison

The Euler options say how to read Euler input.)";

const char* const kFit = R"(Usage: gyre-cli fit KEYS.csv (--omega W.csv | [--direction D.csv] [--magnitude M.csv] [--pattern P.csv --repeat N])
               -o FRAMES.csv --fps F [--alpha A] [--beta B] [--delta D] [--fragment DT]
               [--free i,j,...] [--window ta,tb] [--report R.json] [--order AXES] [--intrinsic|--extrinsic]
       gyre-cli fit PROJECT.gyre --object NAME -o FRAMES.csv --fps F [--report R.json]

Fits the rotation through the keys (a time column is required, at least two keys) to a target
angular velocity, world frame, rad/s (the sketch-editing method, docs/fit.md). Keys keep their
orientation exactly unless freed; positions are not touched. Writes time,qw,qx,qy,qz (and x,y,z
when the keys have positions) at t0 + k/F up to the last key, plus a sample at every key time.

The target, either
  --omega W.csv       samples time,wx,wy,wz, linear between them
or the artist's sketch, one or both of
  --direction D.csv   the direction of the angular velocity: unit vectors x,y,z on the sphere, with
                      an optional time column; without times spread over the window by arc length
  --magnitude M.csv   its size: time,magnitude (rad/s, > 0), linear between samples
and, along the direction,
  --pattern P.csv     a small x,y curve (any unit; x along the direction curve, y across) repeated
  --repeat N          N times along the direction curve, each repetition 1/N of its length;
                      N times the pattern's points at most 1,048,576
A sketch is made into the target as the app makes it: where no direction is drawn the motion keeps
its own, where no speed is drawn its own speed; the window is by default the span the timed
direction and the speed cover (all the keys if the direction is untimed).

With a project (PROJECT.gyre), the object NAME's own sketch, keys and fit settings are fitted as the
app's Fit fits them, and its motion is written as bake writes it, over the scene's time range.

  --fps F        output samples per second, above 0 and at most 1000; changes only the output
  --alpha A      weight of smoothness, the tangential acceleration W_T (default 0.002, >= 0)
  --beta B       weight of the angular-velocity deviation W_A (default 1, > 0)
  --delta D      the largest fragment error accepted, F_n over the target's mean squared speed,
                 in seconds (default 0.1, the paper's value, > 0; docs/fit.md)
  --fragment DT  length of the fragments the error is measured on, seconds (default 0.25);
                 the window may hold at most 100,000 of them
  --free LIST    0-based indices of keys the fit may move, e.g. 1,2,5
  --window ta,tb refit only this span of the keys (default: the target's span); outside it the
                 motion is unchanged, and it stays smooth across the window's ends
  --object NAME  the object of a project to fit; the name must single out one object with keys
  --report FILE  a JSON report: outcome, rounds, iterations, variable frames, largest fragment
                 error (relative, and in rad^2/s), solve time, energy terms before and after, and
                 for a sketch the error against what was drawn before and after

The Euler options say how to read Euler key columns.)";
const char* const kInfo = R"(Usage: gyre-cli info PROJECT.gyre|SCENE

Prints a short summary of a Gyre project (a .gyre file) or of any scene file Assimp reads: its time
range and frame rate, its objects and keyframes, and for each object its parent, keyframes, their
time span and the interpolation. For a scene file it lists every animation (take) with its length
and the nodes it moves, marks those gyre-cli import takes by default and says why, and gives the
frame rate, unit and up axis the import applies and where the file says them.)";

const char* const kBake = R"(Usage: gyre-cli bake PROJECT.gyre --object NAME --fps F -o FRAMES.csv

Writes the motion of one object as the project evaluates it (its interpolation, ScrewBender
subdivision and any applied fit) at start + k/F over the scene's time range, plus a sample at every
key time, as a pose file time,qw,qx,qy,qz,x,y,z: the pose relative to the object's parent, as its
keys are.

  --object NAME  the object; the name must single out one object that has keyframes
  --fps F        samples per second, above 0 and at most 1000
  -o, --output FILE  the output file)";

const char* const kImport = R"(Usage: gyre-cli import SCENE -o PROJECT.gyre [--animation N|N,M,...|all] [--fps F] [--unit METRES]
               [--up y|z] [--time-origin zero|file] [--euler-filter]

Reads any scene file Assimp reads (FBX, OBJ, glTF 2.0, Collada, BVH, DirectX .x, 3DS, ASE, ...) and
writes it as a Gyre project: one object per node, named as the node, with its mesh, its parent and
every key of the chosen animations exactly as the file has them (docs/scene-files.md). What the
project cannot keep (scale animation, morphs, ...) is reported on standard error, and so are the
settings applied.

A file may hold several animations (takes; gyre-cli info lists them). Without --animation:
  one animation, or several that each move nodes no other moves (Blender's glTF), are imported
  together; Blender's FBX takes "Object|Action" give each object its own action (a warning says
  which take each object got); any other overlapping animations are refused with their list.
  --animation N        animation N alone, from 0
  --animation N,M,...  these merged; a node several move takes the last one's keys
  --animation all      every animation merged, the same way

Each setting below defaults to what the file says:
  --fps F              the project's frame rate (FBX time mode, BVH frame time, else the rate on whose
                       frames every key falls); keys are never resampled
  --unit METRES        the length of the file's unit in metres (FBX UnitScaleFactor, Collada <unit>;
                       0.01 for a centimetre file); positions and meshes are scaled to metres
  --up y|z             the file's up axis (FBX UpAxis, Collada up_axis); a Y-up scene is turned Z-up, Gyre's up
  --time-origin zero   the first key at t = 0 for every format (default); file: times as in the file
  --euler-filter       every rotation track in Euler mode, extrinsic xyz (Blender's XYZ Euler), each
                       key's angles the equivalent nearest the key before's, so that a spin the file
                       stores wrapped is a ramp; linear (slerp) keys become euler, cubic ones euler-cubic
  -o, --output FILE    the project file)";

const char* const kExport = R"(Usage: gyre-cli export PROJECT.gyre -o SCENE.(gltf|glb|dae|fbx|obj) [--fps F]

Writes the project as a scene file, the format named by the extension: glTF 2.0 (.gltf with a .bin
beside it, or .glb), Collada (.dae), FBX (.fbx, binary FBX 7.4) or OBJ (.obj with a .mtl; meshes only, no
motion). Every object's motion is baked at the frames and its keys, so every interpolation and fit
plays the same after import.

  --fps F   frames per second of the bake, at most 1000 (default: the project's)
  -o, --output FILE  the scene file)";

const char* const kKeys = R"(Usage: gyre-cli keys PROJECT.gyre --object NAME -o KEYS.csv

Writes the keyframes of one object of a Gyre project as a pose file with the columns
time,qw,qx,qy,qz,x,y,z: the object's pose relative to its parent at each key.

  --object NAME  the object, named as the node in the file it was imported from; the name must
                 single out one object that has keyframes
  -o, --output FILE  the output file)";

QString withCommonOptions(const char* verbHelp) { return QString::fromUtf8(verbHelp) + '\n' + kCommonOptions; }

} // namespace

QString generalHelp() { return QString::fromUtf8(kGeneral); }
QString convertHelp() { return withCommonOptions(kConvert); }
QString interpolateHelp() { return withCommonOptions(kInterpolate); }
QString subdivideHelp() { return withCommonOptions(kSubdivide); }
QString fitHelp() { return withCommonOptions(kFit); }
QString infoHelp() { return QString::fromUtf8(kInfo); }
QString bakeHelp() { return QString::fromUtf8(kBake); }
QString importHelp() { return QString::fromUtf8(kImport); }
QString exportHelp() { return QString::fromUtf8(kExport); }
QString keysHelp() { return QString::fromUtf8(kKeys); }

} // namespace gyre::cli
