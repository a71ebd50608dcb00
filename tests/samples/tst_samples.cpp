// The bundled sample projects: each file is what the code makes now (regenerate with
// `gyre-samples resources/samples`), each opens, and each is what it claims to be.

#include "jobs/sketch_fit.h"
#include "model/project_file.h"
#include "samples/sample_scenes.h"

#include <QDir>
#include <QFile>
#include <QObject>
#include <QTest>

#include <cmath>

using namespace gyre;

class TstSamples : public QObject {
    Q_OBJECT

private slots:
    void bundledFilesAreWhatTheCodeMakes();
    void spinningTopIsTheTableOneTop();
    void meshNormalsPointOutOfTheirTriangles();
};

void TstSamples::bundledFilesAreWhatTheCodeMakes()
{
    for (const samples::SampleScene& sample : samples::allSamples()) {
        const QString path = QDir(QStringLiteral(GYRE_SAMPLES_DIR)).filePath(sample.fileName);
        QFile file(path);
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(path));
        QVERIFY2(file.readAll() == model::projectJson(sample.scene),
                 qPrintable(path + QStringLiteral(" differs: run gyre-samples resources/samples")));
        QCOMPARE(model::readProject(path).objects.size(), sample.scene.objects.size());
    }
}

// The sketch-editing paper's Table 1: 420 frames, 85 keys; and a sketch the fit accepts.
void TstSamples::spinningTopIsTheTableOneTop()
{
    const model::Scene scene = samples::spinningTop().scene;
    QCOMPARE(std::lround((scene.endTime - scene.startTime) * scene.fps), 420L);
    QCOMPARE(scene.objects.size(), std::size_t(1));
    const model::MotionTrack& track = scene.objects[0].track;
    QCOMPARE(track.keys.size(), std::size_t(85));
    QVERIFY(!track.sketch.directionStrokes.empty());
    QVERIFY(track.sketch.patternRepeat > 0);
    const jobs::SketchFitProblem problem = jobs::sketchFitProblem(track);
    QVERIFY(problem.settings.window);
    QVERIFY(problem.settings.window->end > problem.settings.window->start);
}

void TstSamples::meshNormalsPointOutOfTheirTriangles()
{
    for (const samples::SampleScene& sample : samples::allSamples())
        for (const model::SceneObject& object : sample.scene.objects) {
            if (!object.mesh)
                continue;
            const model::Mesh& mesh = *object.mesh;
            QCOMPARE(mesh.normals.size(), mesh.positions.size());
            QCOMPARE(mesh.indices.size() % 3, std::size_t(0));
            for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
                const Eigen::Vector3f& a = mesh.positions[mesh.indices[i]];
                const Eigen::Vector3f face = (mesh.positions[mesh.indices[i + 1]] - a).cross(mesh.positions[mesh.indices[i + 2]] - a);
                if (face.norm() < 1e-6f)
                    continue; // a sliver at the tip or the axis
                for (std::size_t corner = 0; corner < 3; ++corner)
                    QVERIFY(face.dot(mesh.normals[mesh.indices[i + corner]]) > 0.0f);
            }
        }
}

QTEST_GUILESS_MAIN(TstSamples)
#include "tst_samples.moc"
