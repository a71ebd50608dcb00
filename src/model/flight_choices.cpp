#include "model/flight_choices.h"

#include "model/input_error.h"
#include "model/json_field.h"

#include <limits>

namespace gyre::model {

std::vector<int> flightSolutions(const std::vector<Keyframe>& keys)
{
    std::vector<int> choices;
    for (std::size_t i = 0; i + 1 < keys.size(); ++i)
        choices.push_back(keys[i].flightSolution);
    while (!choices.empty() && choices.back() < 0)
        choices.pop_back();
    return choices;
}

void setFlightSolutions(std::vector<Keyframe>& keys, const JsonField& field)
{
    const std::vector<JsonField> choices = field.elements();
    const std::size_t spans = keys.empty() ? 0 : keys.size() - 1;
    if (choices.size() > spans)
        field.fail(FileError::tr("%1 flight choices for %2 spans between the keys: one a span at most")
                       .arg(choices.size())
                       .arg(spans));
    for (std::size_t i = 0; i < choices.size(); ++i)
        keys[i].flightSolution = static_cast<int>(choices[i].integer(-1, std::numeric_limits<int>::max()));
}

} // namespace gyre::model
