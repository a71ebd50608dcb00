#include "model/input_error.h"

#include "core/number_text.h"

namespace gyre {

QString FileError::number(double value) { return QString::fromStdString(formatNumber(value)); }

InputError::InputError(const QString& path, std::string_view message)
    : std::runtime_error(path.toStdString() + ": " + std::string(message))
{
}

InputError::InputError(const QString& path, std::int64_t line, std::string_view message)
    : std::runtime_error(path.toStdString() + ':' + std::to_string(line) + ": " + std::string(message))
{
}

OutputError::OutputError(const QString& path, std::string_view message)
    : std::runtime_error(path.toStdString() + ": " + std::string(message))
{
}

} // namespace gyre
