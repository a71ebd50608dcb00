// The joint rule (model/scene_joints.h) that the viewport's bones and the scene import share.

#include "model/scene_joints.h"

#include <QTest>

#include <memory>

namespace gyre {

namespace {

model::SceneObject object(model::ObjectId id, model::ObjectId parent, std::shared_ptr<const model::Mesh> mesh = nullptr)
{
    model::SceneObject result;
    result.id = id;
    result.parent = parent;
    result.mesh = std::move(mesh);
    return result;
}

} // namespace

class TstSceneJoints : public QObject {
    Q_OBJECT

private slots:
    void meshlessNeighboursAreJointsAndALoneOneIsNot()
    {
        // Hips (1) ─ Knee (2), and a lone Target (3) beside a mesh object (4) with a meshless child (5).
        auto block = std::make_shared<model::Mesh>();
        model::Scene scene;
        scene.objects = {object(1, model::kNoObject), object(2, 1), object(3, model::kNoObject),
                         object(4, model::kNoObject, block), object(5, 4)};
        QCOMPARE(model::findJoints(scene), (std::vector<bool>{true, true, false, false, false}));
    }

    // A skin's joint is a joint though no meshless object touches it (a one-bone armature); one with a
    // mesh of its own or an Empty is not.
    void aSkinsJointIsAJoint()
    {
        auto skinned = std::make_shared<model::Mesh>();
        skinned->skin.joints = {2, 3, 4};
        auto block = std::make_shared<model::Mesh>();
        model::Scene scene;
        scene.objects = {object(1, model::kNoObject, skinned), object(2, model::kNoObject), object(3, model::kNoObject, block),
                         object(4, model::kNoObject), object(5, model::kNoObject)};
        scene.objects[3].empty = true;
        QCOMPARE(model::findJoints(scene), (std::vector<bool>{false, true, false, false, false}));
        std::vector<std::size_t> parents;
        model::findParentIndices(scene, parents);
        QCOMPARE(parents, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
    }
};

} // namespace gyre

QTEST_GUILESS_MAIN(gyre::TstSceneJoints)
#include "tst_scene_joints.moc"
