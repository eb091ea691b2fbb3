/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
// Disk/polygon areas (the 2D models) against closed forms and an independent
// exact x-integration (referenceArea.H).
#include "diskOverlap.H"
#include "testHarness.H"
#include "referenceArea.H"

#include <random>
#include <vector>

using namespace sphereOverlap;
using testHarness::near;

namespace
{
double area(const vec2& c, double R, const std::vector<vec2>& poly)
{
    return diskPolygonArea(c, R, [&](std::size_t i) { return poly[i]; }, poly.size());
}

std::vector<reference::p2> shifted(const std::vector<vec2>& poly, const vec2& c)
{
    std::vector<reference::p2> out;
    for (const vec2& p : poly) out.push_back({p.x - c.x, p.y - c.y});
    return out;
}
}

int main()
{
    const double pi = 3.14159265358979323846;
    const double R = 0.7;
    const double A = pi*R*R;
    const std::vector<vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

    near("disk inside the square", area({0.5, 0.5}, 0.3, square), pi*0.09, 1e-15);
    near("disk on a corner: a quarter", area({0, 0}, R, square), A/4, 1e-15);
    near("disk on an edge: a half", area({0.5, 0}, 0.3, square), pi*0.09/2, 1e-15);
    near("square inside the disk", area({0.5, 0.5}, 2, square), 1, 1e-15);
    near("disk outside", area({3, 3}, R, square), 0, 0);
    const std::vector<vec2> reversed(square.rbegin(), square.rend());
    near("orientation does not matter", area({0.2, 0.9}, R, reversed), area({0.2, 0.9}, R, square), 1e-15);
    near("tangent from outside", area({1.7, 0.5}, R, square), 0, 1e-15);
    near("inscribed disk, tangent to all four edges", area({0.5, 0.5}, 0.5, square), pi/4, 1e-15);

    // random convex polygons (sorted random points on an ellipse) and disks
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    double worst = 0;
    for (int t = 0; t < 500; ++t)
    {
        const int n = 3 + int(6*u(rng));
        std::vector<double> angles(n);
        for (double& a : angles) a = 2*pi*u(rng);
        std::sort(angles.begin(), angles.end());
        const double ax = 0.2 + u(rng), ay = 0.2 + u(rng);
        std::vector<vec2> poly;
        for (double a : angles) poly.push_back({ax*std::cos(a), ay*std::sin(a)});
        const vec2 c{2*u(rng) - 1, 2*u(rng) - 1};
        const double r = 0.05 + u(rng);
        const double want = reference::diskPolygonArea(r, shifted(poly, c));
        worst = std::max(worst, std::fabs(area(c, r, poly) - want)/(pi*r*r));
    }
    std::printf("disk/polygon worst error %.2e of the disk area (500 random cases)\n", worst);
    near("random convex polygons = x-integration (rel. to disk)", worst, 0, 1e-13);

    // a non-convex L-shape is the sum of its two rectangles
    {
        const std::vector<vec2> L{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
        const std::vector<vec2> r1{{0, 0}, {2, 0}, {2, 1}, {0, 1}}, r2{{0, 1}, {1, 1}, {1, 2}, {0, 2}};
        double worstL = 0;
        for (int t = 0; t < 100; ++t)
        {
            const vec2 c{3*u(rng) - 0.5, 3*u(rng) - 0.5};
            const double r = 0.1 + 1.5*u(rng);
            worstL = std::max(worstL, std::fabs(area(c, r, L) - area(c, r, r1) - area(c, r, r2))/(pi*r*r));
        }
        near("non-convex polygon = sum of its convex parts", worstL, 0, 1e-14);
    }
    return testHarness::summary("disks");
}
