/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
// Lattice counting (voxel and hybrid models) against a point-by-point scan,
// partition of the ball by boxes, and convergence of count * voxel volume to
// the sphere volume at the order a voxelised surface implies.
#include "latticeCount.H"
#include "testHarness.H"

#include <random>
#include <vector>

using namespace sphereOverlap;
using testHarness::near;

namespace
{
// The definition itself: every lattice point of a generous index range
long scanCount(const vec3& c, double R, const lattice& L, const vec3& lo, const vec3& hi)
{
    long n = 0;
    auto idx = [](double x, double o, double h) { return long(std::floor((x - o)/h)); };
    for (long i = idx(c.x - R, L.o.x, L.h.x) - 2; i <= idx(c.x + R, L.o.x, L.h.x) + 2; ++i)
    for (long j = idx(c.y - R, L.o.y, L.h.y) - 2; j <= idx(c.y + R, L.o.y, L.h.y) + 2; ++j)
    for (long k = idx(c.z - R, L.o.z, L.h.z) - 2; k <= idx(c.z + R, L.o.z, L.h.z) + 2; ++k)
    {
        const vec3 p{L.o.x + (i + 0.5)*L.h.x, L.o.y + (j + 0.5)*L.h.y, L.o.z + (k + 0.5)*L.h.z};
        const vec3 d = p - c;
        if (dot(d, d) <= R*R && p.x >= lo.x && p.x < hi.x && p.y >= lo.y && p.y < hi.y
         && p.z >= lo.z && p.z < hi.z) ++n;
    }
    return n;
}
}

int main()
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);

    // random balls, anisotropic lattices and boxes: row count = scan
    long worst = 0, visitedWorst = 0;
    for (int t = 0; t < 300; ++t)
    {
        const double R = 0.2 + u(rng);
        const vec3 c{u(rng), u(rng), u(rng)};
        const lattice L{{u(rng), u(rng), u(rng)}, {0.05 + 0.3*u(rng), 0.05 + 0.3*u(rng), 0.05 + 0.3*u(rng)}};
        const vec3 lo{c.x - 1.5*u(rng), c.y - 1.5*u(rng), c.z - 1.5*u(rng)};
        const vec3 hi{lo.x + 2*u(rng), lo.y + 2*u(rng), lo.z + 2*u(rng)};
        worst = std::max(worst, std::labs(latticeCount(c, R, L, lo, hi) - scanCount(c, R, L, lo, hi)));
        long visited = 0;
        forEachLatticePoint(c, R, L, lo, hi, [&](const vec3&) { ++visited; });
        visitedWorst = std::max(visitedWorst, std::labs(visited - scanCount(c, R, L, lo, hi)));
    }
    near("row count = point scan (300 random balls, lattices, boxes)", double(worst), 0, 0);
    near("points visited = point scan", double(visitedWorst), 0, 0);

    // lattice points lying exactly on box planes: boxes that tile space
    // count every point once
    {
        const lattice L{{0, 0, 0}, {0.1, 0.1, 0.1}};
        const vec3 c{0.52, 0.5, 0.47};
        const double R = 0.33;
        long sum = 0;
        const double planes[4] = {0.05, 0.35, 0.55, 0.95};   // on lattice points
        for (int i = 0; i < 3; ++i) for (int j = 0; j < 3; ++j) for (int k = 0; k < 3; ++k)
        {
            sum += latticeCount(c, R, L, {planes[i], planes[j], planes[k]},
                                {planes[i + 1], planes[j + 1], planes[k + 1]});
        }
        near("boxes through lattice points partition the count", double(sum),
             double(latticeCount(c, R, L)), 0);
        near("the partition holds the ball", double(latticeCount(c, R, L)),
             double(scanCount(c, R, L, {-9, -9, -9}, {9, 9, 9})), 0);
    }

    // voxel volume -> sphere volume; averaged over random offsets the error
    // falls like (voxels per diameter)^-2 or faster
    {
        const double R = 1;
        double err[2];
        const int nPerDiameter[2] = {10, 40};
        for (int m = 0; m < 2; ++m)
        {
            const double h = 2*R/nPerDiameter[m];
            double sumSq = 0;
            for (int t = 0; t < 50; ++t)
            {
                const lattice L{{u(rng)*h, u(rng)*h, u(rng)*h}, {h, h, h}};
                const double rel = latticeCount({0, 0, 0}, R, L)*h*h*h/sphereVolume(R) - 1;
                sumSq += rel*rel;
            }
            err[m] = std::sqrt(sumSq/50);
        }
        std::printf("voxel volume rms error: %.2e at 10, %.2e at 40 per diameter (order %.2f)\n",
                    err[0], err[1], std::log(err[0]/err[1])/std::log(4.0));
        near("voxel volume error at 40 per diameter below 1 %", err[1] < 1e-2 ? 0 : err[1], 0, 0);
        near("voxel volume error order >= 1.5", std::log(err[0]/err[1])/std::log(4.0) >= 1.5 ? 0 : 1, 0, 0);
    }

    // the sub-grid table: eight entries = row count on the sphere's own lattice
    {
        long worstTable = 0, worstTotal = 0;
        for (int n : {1, 5, 20, 33})
        {
            const sphereLatticeTable table(n);
            for (int t = 0; t < 200; ++t)
            {
                const double R = 0.1 + u(rng);
                const vec3 c{u(rng), u(rng), u(rng)};
                const lattice L{{c.x - R, c.y - R, c.z - R}, {2*R/n, 2*R/n, 2*R/n}};
                const vec3 lo{c.x - 1.5*R*u(rng), c.y - 1.5*R*u(rng), c.z - 1.5*R*u(rng)};
                const vec3 hi{lo.x + 2*R*u(rng), lo.y + 2*R*u(rng), lo.z + 2*R*u(rng)};
                worstTable = std::max(worstTable, std::labs(table.count(c, R, lo, hi) - scanCount(c, R, L, lo, hi)));
                worstTotal = std::max(worstTotal, std::labs(table.total() - latticeCount(c, R, L)));
            }
        }
        // 2D: one layer through the centre in the flat direction
        for (int flat = 0; flat < 3; ++flat)
        {
            const int n = 17;
            const sphereLatticeTable table(n, flat);
            for (int t = 0; t < 200; ++t)
            {
                const double R = 0.1 + u(rng);
                const vec3 c{u(rng), u(rng), u(rng)};
                vec3 h{2*R/n, 2*R/n, 2*R/n};
                (flat == 0 ? h.x : flat == 1 ? h.y : h.z) = 2*R;
                const lattice L{{c.x - R, c.y - R, c.z - R}, h};
                const vec3 lo{c.x - 1.5*R*u(rng), c.y - 1.5*R*u(rng), c.z - 1.5*R*u(rng)};
                const vec3 hi{lo.x + 2*R*u(rng), lo.y + 2*R*u(rng), lo.z + 2*R*u(rng)};
                worstTable = std::max(worstTable, std::labs(table.count(c, R, lo, hi) - scanCount(c, R, L, lo, hi)));
                worstTotal = std::max(worstTotal, std::labs(table.total() - latticeCount(c, R, L)));
            }
        }
        near("sub-grid table count = point scan (n = 1, 5, 20, 33; flat 17 x 17 in x, y, z)", double(worstTable), 0, 0);
        near("sub-grid table total = row count", double(worstTotal), 0, 0);
    }
    return testHarness::summary("lattice");
}
