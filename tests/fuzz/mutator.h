#pragma once
// Mutations of valid files for the mutation test: the edits that have broken readers elsewhere,
// applied one to three at a time by a seeded generator, so that a failure replays from its seed.

#include <QByteArray>

#include <random>

namespace gyre::fuzz {

class Mutator {
public:
    explicit Mutator(unsigned seed) : engine_(seed) {}

    // A mutant of `bytes`. `json` adds edits of the JSON structure (when the bytes still parse), and
    // of a version 3 project's header and blocks.
    QByteArray mutate(const QByteArray& bytes, bool json);

private:
    std::size_t below(std::size_t count); // uniform in [0, count); 0 when count is 0
    void flipBytes(QByteArray& bytes);
    void insertBytes(QByteArray& bytes);
    void deleteBytes(QByteArray& bytes);
    void duplicateLine(QByteArray& bytes);
    void truncate(QByteArray& bytes);
    void replaceNumber(QByteArray& bytes);
    void editJson(QByteArray& bytes);
    void editBinaryProject(QByteArray& bytes);

    std::mt19937 engine_;
};

} // namespace gyre::fuzz
