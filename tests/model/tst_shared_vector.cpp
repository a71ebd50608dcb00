// SharedVector, the copy-on-write vector of a track's keys: copies share their elements until one is
// changed, a change never shows in another copy, and reading never copies. A scene copied whole (the
// autosave's snapshot) shares every track's keys with the document.

#include "model/commands/import_objects_command.h"
#include "model/commands/replace_keyframes_command.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/document.h"
#include "model/key_edits.h"
#include "model/shared_vector.h"

#include <QTest>

#include <cmath>
#include <thread>
#include <vector>

using namespace gyre::model;

class TstSharedVector : public QObject {
    Q_OBJECT

private slots:
    void copiesShareUntilChanged();
    void readingNeverCopies();
    void everyWayOfChangingCopiesFirst();
    void aSceneCopySharesItsKeys();
    void aCopyIsReadWhileTheDocumentChanges();
};

void TstSharedVector::copiesShareUntilChanged()
{
    SharedVector<int> original(std::vector<int>{1, 2, 3});
    SharedVector<int> copy = original;
    QVERIFY(copy.sharesElementsWith(original));
    copy.edit().push_back(4);
    QVERIFY(!copy.sharesElementsWith(original));
    QCOMPARE(original.vector(), (std::vector<int>{1, 2, 3}));
    QCOMPARE(copy.vector(), (std::vector<int>{1, 2, 3, 4}));
    // A vector no other copy shares is changed in place.
    const int* storage = copy.vector().data();
    copy[0] = 10;
    QCOMPARE(copy.vector().data(), storage);
    QCOMPARE(copy.front(), 10);
}

void TstSharedVector::readingNeverCopies()
{
    const SharedVector<int> original(std::vector<int>{1, 2, 3});
    const SharedVector<int> copy = original;
    int sum = 0;
    for (const int value : copy)
        sum += value;
    QCOMPARE(sum, 6);
    QCOMPARE(copy[2], 3);
    QCOMPARE(copy.back(), 3);
    const std::vector<int>& asVector = copy;
    QCOMPARE(asVector.size(), std::size_t{3});
    QVERIFY(copy.sharesElementsWith(original));
}

void TstSharedVector::everyWayOfChangingCopiesFirst()
{
    const SharedVector<int> original(std::vector<int>{5, 6, 7});
    const auto changedCopy = [&](auto change) {
        SharedVector<int> copy = original;
        change(copy);
        QVERIFY(!copy.sharesElementsWith(original));
        QCOMPARE(original.vector(), (std::vector<int>{5, 6, 7}));
    };
    changedCopy([](SharedVector<int>& v) { v[1] = 0; });
    changedCopy([](SharedVector<int>& v) { v.front() = 0; });
    changedCopy([](SharedVector<int>& v) { v.back() = 0; });
    changedCopy([](SharedVector<int>& v) { *v.begin() = 0; });
    changedCopy([](SharedVector<int>& v) { v.push_back(0); });
    changedCopy([](SharedVector<int>& v) { v.emplace_back(0); });
    changedCopy([](SharedVector<int>& v) { v.resize(1); });
    changedCopy([](SharedVector<int>& v) { v.clear(); });
    changedCopy([](SharedVector<int>& v) { v = std::vector<int>{1}; });
}

void TstSharedVector::aSceneCopySharesItsKeys()
{
    Document document;
    SceneObject object;
    object.id = 1;
    object.track.keys = std::vector<Keyframe>{{0.0, {}, true}, {1.0, {}, true}};
    document.undoStack().push(new ImportObjectsCommand(document, {object}));

    const Scene snapshot = document.scene();
    QVERIFY(snapshot.objects[0].track.keys.sharesElementsWith(document.scene().objects[0].track.keys));

    // An edit through the undo stack changes the document, not the snapshot.
    const Eigen::Quaterniond turned(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()));
    document.undoStack().push(new SetKeyframeOrientationCommand(document, 1, 1, turned));
    QVERIFY(document.scene().objects[0].track.keys[1].pose.orientation.isApprox(turned));
    QVERIFY(snapshot.objects[0].track.keys[1].pose.orientation.isApprox(Eigen::Quaterniond::Identity()));
    document.undoStack().undo();
    QVERIFY(document.scene().objects[0].track.keys[1].pose.orientation.isApprox(Eigen::Quaterniond::Identity()));
}

// The autosave's use: a copy read on a worker while the UI thread edits the document. Under the
// sanitizer build a write into storage the worker reads would be a reported error.
void TstSharedVector::aCopyIsReadWhileTheDocumentChanges()
{
    Document document;
    SceneObject object;
    object.id = 1;
    std::vector<Keyframe> keys(20'000);
    for (std::size_t i = 0; i < keys.size(); ++i)
        keys[i].time = static_cast<double>(i);
    object.track.keys = std::move(keys);
    document.undoStack().push(new ImportObjectsCommand(document, {object}));

    const Scene snapshot = document.scene();
    double sum = 0.0;
    std::thread reader([&] {
        for (int pass = 0; pass < 20; ++pass)
            for (const Keyframe& key : snapshot.objects[0].track.keys)
                sum += key.time;
    });
    // Each edit keys the object as the window's Add Keyframe does (a new list of keys) and turns one
    // key, which writes into the document's own copy of the elements.
    const Eigen::Quaterniond turned(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()));
    for (int edit = 0; edit < 20; ++edit) {
        const std::vector<Keyframe> keyed = withKeys(document.object(1)->track.keys, {Keyframe{20'000.5 + edit, {}, true}});
        document.undoStack().push(new ReplaceKeyframesCommand(document, {{1, keyed}}, ReplaceKeyframesCommand::Edit::Insert));
        document.undoStack().push(new SetKeyframeOrientationCommand(document, 1, static_cast<std::size_t>(edit), turned));
    }
    reader.join();
    const double n = 20'000.0;
    QCOMPARE(sum, 20.0 * n * (n - 1.0) / 2.0);
    QCOMPARE(snapshot.objects[0].track.keys.size(), std::size_t{20'000});
    QCOMPARE(document.scene().objects[0].track.keys.size(), std::size_t{20'020});
}

QTEST_GUILESS_MAIN(TstSharedVector)
#include "tst_shared_vector.moc"
