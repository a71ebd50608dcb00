#pragma once
// What commands check before they are pushed, so that a command on the stack always applies. Each
// throws std::invalid_argument with a message for the person who asked for the change.

#include "model/commands/change_value_command.h"
#include "model/document.h"

#include <QCoreApplication>
#include <QString>

#include <cstddef>

namespace gyre::model {

const SceneObject& requireObject(const Document& document, ObjectId object);
const Keyframe& requireKeyframe(const Document& document, ObjectId object, std::size_t key);
const DirectionStroke& requireStroke(const Document& document, ObjectId object, std::size_t stroke);

// The target of a change to the object, to its keyframe at index `key`, to its stroke at index
// `stroke`, once they are known to exist.
FieldTarget objectTarget(const Document& document, ObjectId object);
FieldTarget keyframeTarget(const Document& document, ObjectId object, std::size_t key);
FieldTarget strokeTarget(const Document& document, ObjectId object, std::size_t stroke);

// `value` after `check` has accepted it (and perhaps normalised it).
template <class Value, class Check>
Value checked(Value value, Check check)
{
    check(value);
    return value;
}

// The text that the undo history shows for a command, in the user's language. Each command marks its
// text with QT_TRANSLATE_NOOP("gyre::model::Command", ...), so that lupdate finds it in that context.
inline QString commandText(const char* text) { return QCoreApplication::translate("gyre::model::Command", text); }

} // namespace gyre::model
