#include "model/commands/command_checks.h"

#include <stdexcept>
#include <string>

namespace gyre::model {

namespace {

void requireIndex(std::size_t index, std::size_t size, const char* what, ObjectId object)
{
    if (index >= size)
        throw std::invalid_argument("object " + std::to_string(object) + " has no " + what + " " +
                                    std::to_string(index) + " (it has " + std::to_string(size) + ")");
}

} // namespace

const SceneObject& requireObject(const Document& document, ObjectId object)
{
    if (const SceneObject* found = document.object(object))
        return *found;
    throw std::invalid_argument("the scene has no object " + std::to_string(object));
}

const Keyframe& requireKeyframe(const Document& document, ObjectId object, std::size_t key)
{
    const std::vector<Keyframe>& keys = requireObject(document, object).track.keys;
    requireIndex(key, keys.size(), "keyframe", object);
    return keys[key];
}

const DirectionStroke& requireStroke(const Document& document, ObjectId object, std::size_t stroke)
{
    const std::vector<DirectionStroke>& strokes = requireObject(document, object).track.sketch.directionStrokes;
    requireIndex(stroke, strokes.size(), "stroke", object);
    return strokes[stroke];
}

FieldTarget objectTarget(const Document& document, ObjectId object)
{
    requireObject(document, object);
    return {object, 0};
}

FieldTarget keyframeTarget(const Document& document, ObjectId object, std::size_t key)
{
    requireKeyframe(document, object, key);
    return {object, key};
}

FieldTarget strokeTarget(const Document& document, ObjectId object, std::size_t stroke)
{
    requireStroke(document, object, stroke);
    return {object, stroke};
}

} // namespace gyre::model
