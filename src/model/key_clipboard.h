#pragma once
// What Edit ▸ Copy puts on the clipboard: keys of one or more objects, or one object's pose, as JSON
// text that reads in a text editor. Each key is written as the project file writes keyframes in JSON
// (project_file.h, keyframeJson), its time relative to the first key copied:
//
//   {"format": "gyre-keys", "version": 1, "pose": false,
//    "objects": [{"name": "Top", "keyframes": [{"time": 0, "orientation": [1, 0, 0, 0], ...}, ...]}]}
//
// A pose is one object with one key at time 0 and "pose": true. Reading checks everything as a
// project file's reader does and throws FieldError naming the field, so text that is not this
// format is refused whole and pastes nothing.

#include "model/scene.h"

#include <QByteArray>
#include <QString>

#include <cstddef>
#include <vector>

namespace gyre::model {

inline constexpr char kKeyClipboardFormat[] = "gyre-keys";
inline constexpr char kKeyClipboardMimeType[] = "application/x-gyre-keys";
// Larger clipboard text is refused before it is parsed: 64 MiB, some 500,000 keys at about 130
// bytes each.
inline constexpr qsizetype kMaxKeyClipboardBytes = qsizetype{64} << 20;

struct CopiedKeys {
    QString name;                // the object's name, to paste onto the object of that name
    std::vector<Keyframe> keys;  // times relative to the first key copied, increasing
};

struct KeyClipboard {
    bool pose = false; // one object, one key at time 0: its pose
    std::vector<CopiedKeys> objects;
};

QByteArray keyClipboardJson(const KeyClipboard& clipboard);
// Throws FieldError, whose message names the field (or says the text is not Gyre's keys).
KeyClipboard parseKeyClipboard(const QByteArray& text);

} // namespace gyre::model
