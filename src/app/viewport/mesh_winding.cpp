#include "app/viewport/mesh_winding.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace gyre::app {

namespace {

// The key of a position: its three floats' bits, +0 for −0 so that the two zeros meet.
struct PositionKey {
    std::uint32_t bits[3];
    bool operator==(const PositionKey&) const = default;
};

struct PositionKeyHash {
    std::size_t operator()(const PositionKey& key) const
    {
        std::uint64_t hash = 1469598103934665603ULL; // FNV-1a over the three words
        for (std::uint32_t word : key.bits)
            hash = (hash ^ word) * 1099511628211ULL;
        return static_cast<std::size_t>(hash);
    }
};

PositionKey keyOf(const Eigen::Vector3f& position)
{
    PositionKey key{};
    for (int i = 0; i < 3; ++i) {
        const float value = position[i] + 0.0F; // −0 + 0 = +0
        std::memcpy(&key.bits[i], &value, sizeof value);
    }
    return key;
}

// One number per distinct position, for each vertex.
std::vector<std::uint32_t> joinedVertices(const model::Mesh& mesh)
{
    std::unordered_map<PositionKey, std::uint32_t, PositionKeyHash> ids;
    ids.reserve(mesh.positions.size());
    std::vector<std::uint32_t> joined;
    joined.reserve(mesh.positions.size());
    for (const Eigen::Vector3f& position : mesh.positions)
        joined.push_back(ids.try_emplace(keyOf(position), static_cast<std::uint32_t>(ids.size())).first->second);
    return joined;
}

} // namespace

MeshWinding meshWinding(const model::Mesh& mesh)
{
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
        return MeshWinding::Open;
    const std::vector<std::uint32_t> joined = joinedVertices(mesh);
    // Each undirected edge's walks: +1 from its lower end to its higher, −1 back. Closed: all zero.
    std::unordered_map<std::uint64_t, int> walks;
    walks.reserve(mesh.indices.size());
    double sixVolume = 0.0;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const std::uint32_t corners[3] = {joined[mesh.indices[i]], joined[mesh.indices[i + 1]], joined[mesh.indices[i + 2]]};
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t from = corners[k];
            const std::uint32_t to = corners[(k + 1) % 3];
            const auto [low, high] = std::minmax(from, to);
            walks[(std::uint64_t{low} << 32) | high] += from < to ? 1 : -1;
        }
        const Eigen::Vector3d a = mesh.positions[mesh.indices[i]].cast<double>();
        const Eigen::Vector3d b = mesh.positions[mesh.indices[i + 1]].cast<double>();
        const Eigen::Vector3d c = mesh.positions[mesh.indices[i + 2]].cast<double>();
        sixVolume += a.dot(b.cross(c));
    }
    for (const auto& [edge, balance] : walks)
        if (balance != 0)
            return MeshWinding::Open;
    return sixVolume < 0.0 ? MeshWinding::Clockwise : MeshWinding::CounterClockwise;
}

} // namespace gyre::app
