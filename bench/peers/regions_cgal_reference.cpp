// Intersection curves against CGAL's Polygon_mesh_processing::surface_intersection (issue 38's
// independent reference), on meshes whose curves CGAL computes: closed spheres and tori, wavy
// sheets, and a model (glmark2-data's bunny, scaled to the scene) against a sphere, crossing at
// random placements (seeded). For each case: our curves (find_regions
// on the exact pair list) and CGAL's polylines as point sets, the largest distance from a point
// of either to the other's segments, over the scene's size; the curves' total lengths; and the
// number of closed curves. Prints a table; exit 1 when a distance exceeds 1e-9 of the scene's
// size or the lengths differ by more than 1e-9 relative. Run by hand (records/).
//
// Usage: regions_cgal_reference [cases (default 40)] [seed (default 38)]

#include "collidescope/mesh.hpp"
#include "collidescope/pipeline.hpp"
#include "collidescope/regions.hpp"
#include "datasets/generated_source.hpp"
#include "datasets/shapes.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <vector>

namespace {

using namespace collidescope;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
constexpr double k_pi = std::numbers::pi;

MeshData sphere(std::uint32_t segments, const Vec3& centre, double radius) {
    MeshData mesh;
    mesh.triangles = datasets::sphere_triangles(segments, segments / 2);
    mesh.vertices.resize(segments * (segments / 2) + 2);
    datasets::unit_sphere_vertices(segments, segments / 2, mesh.vertices);
    for (Vec3& v : mesh.vertices) v = centre + radius * v;
    return mesh;
}

MeshData torus(std::uint32_t around, std::uint32_t tube, const Vec3& centre, double R, double r, double tilt) {
    MeshData mesh;
    for (std::uint32_t j = 0; j < tube; ++j) {  // vertex (i, j) at j * around + i (torus_triangles)
        for (std::uint32_t i = 0; i < around; ++i) {
            const double u = 2 * k_pi * i / around, v = 2 * k_pi * (j + 0.37) / tube;
            const Vec3 p((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
            mesh.vertices.push_back(centre + Vec3(p.x(), std::cos(tilt) * p.y() - std::sin(tilt) * p.z(),
                                                  std::sin(tilt) * p.y() + std::cos(tilt) * p.z()));
        }
    }
    mesh.triangles = datasets::torus_triangles(around, tube);
    return mesh;
}

MeshData wavy_sheet(std::uint32_t cells, double z, double amplitude, double phase) {
    MeshData mesh;
    for (std::uint32_t j = 0; j <= cells; ++j) {  // vertex (i, j) at j * (cells + 1) + i (grid_triangles)
        for (std::uint32_t i = 0; i <= cells; ++i) {
            const double x = -2 + 4.0 * i / cells, y = -2 + 4.0 * j / cells;
            mesh.vertices.emplace_back(x, y, z + amplitude * std::sin(2 * x + phase) * std::cos(1.5 * y));
        }
    }
    mesh.triangles = datasets::grid_triangles(cells + 1, cells + 1);
    return mesh;
}

Mesh to_cgal(const MeshData& data) {
    Mesh mesh;
    std::vector<Mesh::Vertex_index> vertices;
    for (const Vec3& v : data.vertices) vertices.push_back(mesh.add_vertex(Kernel::Point_3(v.x(), v.y(), v.z())));
    for (const TriIndices& t : data.triangles) mesh.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]);
    return mesh;
}

Frame frame_of(const std::vector<MeshData>& meshes) {
    Frame frame;
    for (const MeshData& mesh : meshes) {
        auto topology = std::make_shared<Topology>();
        topology->triangles = mesh.triangles;
        topology->vertex_count = static_cast<std::uint32_t>(mesh.vertices.size());
        topology->revision = next_topology_revision();
        ObjectFrame object;
        object.topology = topology;
        object.vertices = FrameVertices(mesh.vertices);
        frame.objects.push_back(std::move(object));
    }
    return frame;
}

double point_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    return (p - (a + t * ab)).norm();
}

// The largest distance from a point of `from` to the segments of `to`.
double farthest(const std::vector<std::vector<Vec3>>& from, const std::vector<std::vector<Vec3>>& to) {
    double worst = 0;
    for (const auto& line : from) {
        for (const Vec3& p : line) {
            double best = INFINITY;
            for (const auto& other : to) {
                for (std::size_t k = 0; k + 1 < other.size(); ++k) best = std::min(best, point_segment(p, other[k], other[k + 1]));
                if (other.size() == 1) best = std::min(best, (p - other[0]).norm());
            }
            worst = std::max(worst, best);
        }
    }
    return worst;
}

double length(const std::vector<std::vector<Vec3>>& lines) {
    double total = 0;
    for (const auto& line : lines) {
        for (std::size_t k = 0; k + 1 < line.size(); ++k) total += (line[k + 1] - line[k]).norm();
    }
    return total;
}

}  // namespace

int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 40;
    const unsigned seed = argc > 2 ? static_cast<unsigned>(std::atoi(argv[2])) : 38u;
    std::printf("regions_cgal_reference: %d cases, seed %u\n", cases, seed);
    std::printf("%-4s %-16s %6s %6s %8s %8s %12s %12s %10s\n", "case", "meshes", "loops", "cgal", "ours", "cgal",
                "ours-cgal", "cgal-ours", "len diff");
    // The model: the bunny, scaled into [-1, 1]^3 (glmark2-data; skipped with a note without it).
    MeshData bunny;
    try {
        bunny = read_mesh_file("/usr/share/glmark2/models/bunny.obj");
        Eigen::AlignedBox3d box;
        for (const Vec3& v : bunny.vertices) box.extend(v);
        for (Vec3& v : bunny.vertices) v = 2.0 * (v - box.center()) / box.sizes().maxCoeff();
    } catch (const std::exception& error) {
        std::printf("no model case: %s\n", error.what());
    }
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    int failures = 0;
    for (int c = 0; c < cases; ++c) {
        const Vec3 offset(0.6 * unit(rng), 0.6 * unit(rng), 0.6 * unit(rng));
        std::vector<MeshData> meshes;
        const char* kind = nullptr;
        switch (bunny.vertices.empty() ? c % 3 : c % 4) {
            case 0:
                meshes = {sphere(24 + 8 * (c % 4), Vec3::Zero(), 1.0), sphere(30, offset + Vec3(1.0, 0, 0), 0.8)};
                kind = "sphere/sphere";
                break;
            case 1:
                meshes = {torus(64, 16, Vec3::Zero(), 1.2, 0.35, 0.0), sphere(32, offset + Vec3(1.2, 0, 0), 0.6)};
                kind = "torus/sphere";
                break;
            case 2:
                meshes = {wavy_sheet(40, 0, 0.3, unit(rng)), torus(48, 12, offset, 1.0, 0.3, 0.5 + unit(rng))};
                kind = "sheet/torus";
                break;
            default:
                meshes = {bunny, sphere(40, offset * 0.8, 0.45)};
                kind = "bunny/sphere";
                break;
        }
        Pipeline pipeline({"aabb", false, 1});
        const Frame frame = frame_of(meshes);
        const std::vector<Region> regions = find_regions(frame, pipeline.process(frame).colliding_pairs);
        std::vector<std::vector<Vec3>> ours;
        std::uint32_t our_loops = 0;
        for (const Region& region : regions) {
            for (const IntersectionCurve& curve : region.curves) {
                std::vector<Vec3> line = curve.points;
                if (curve.closed && !line.empty()) line.push_back(line.front());
                ours.push_back(std::move(line));
                our_loops += curve.closed ? 1 : 0;
            }
        }
        const Mesh a = to_cgal(meshes[0]), b = to_cgal(meshes[1]);
        std::vector<std::vector<Kernel::Point_3>> polylines;
        CGAL::Polygon_mesh_processing::surface_intersection(a, b, std::back_inserter(polylines));
        std::vector<std::vector<Vec3>> theirs;
        std::uint32_t their_loops = 0;
        for (const auto& polyline : polylines) {
            std::vector<Vec3> line;
            for (const auto& p : polyline) line.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
            their_loops += line.size() > 2 && line.front() == line.back() ? 1 : 0;
            theirs.push_back(std::move(line));
        }
        const double scale = 4.0;
        const double d1 = farthest(ours, theirs) / scale, d2 = farthest(theirs, ours) / scale;
        const double l1 = length(ours), l2 = length(theirs);
        const double diff = l2 > 0 ? std::abs(l1 - l2) / l2 : std::abs(l1);
        const bool ok = d1 <= 1e-9 && d2 <= 1e-9 && diff <= 1e-9;
        failures += ok ? 0 : 1;
        std::printf("%-4d %-16s %6u %6u %8.5f %8.5f %12.2e %12.2e %10.2e%s\n", c, kind, our_loops, their_loops, l1, l2, d1,
                    d2, diff, ok ? "" : "  MISMATCH");
    }
    std::printf("%d of %d cases within 1e-9 (points both ways, over the scene's size 4; lengths relative)\n",
                cases - failures, cases);
    return failures == 0 ? 0 : 1;
}
