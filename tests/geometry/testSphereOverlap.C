/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
// Exact ball/cell overlap against closed forms and against an independent
// numerical integration: the convex cell is sliced at height z, the area of
// disk ∩ slice polygon is integrated exactly in x piece by piece, and that
// area is integrated over z by adaptive Gauss-Kronrod.
#include "sphereOverlap.H"
#include "testHarness.H"
#include "referenceArea.H"

#include <algorithm>
#include <functional>
#include <random>
#include <vector>

using namespace sphereOverlap;
using testHarness::near;

namespace
{
using reference::p2;
using reference::diskPolygonArea;

// Slice of a convex polyhedron (vertices, edges) at height z, centred on c.
std::vector<p2> slice(const std::vector<vec3>& v, const std::vector<std::pair<int,int>>& e,
                      const vec3& c, double z)
{
    std::vector<p2> pts;
    for (auto [i, j] : e)
    {
        const vec3 a = v[i] - c, b = v[j] - c;
        if ((a.z - z)*(b.z - z) < 0 || (a.z == z) )
        {
            const double t = (a.z == b.z) ? 0 : (z - a.z)/(b.z - a.z);
            pts.push_back({a.x + t*(b.x - a.x), a.y + t*(b.y - a.y)});
        }
    }
    if (pts.size() < 3) return {};
    p2 m{0, 0};
    for (auto p : pts) { m.x += p.x/pts.size(); m.y += p.y/pts.size(); }
    std::sort(pts.begin(), pts.end(), [&](p2 a, p2 b)
        { return std::atan2(a.y - m.y, a.x - m.x) < std::atan2(b.y - m.y, b.x - m.x); });
    return pts;
}

double gaussKronrod(const std::function<double(double)>& f, double a, double b,
                    double tol, int depth)
{
    static const double xk[8] = {0.991455371120812639, 0.949107912342758525,
        0.864864423359769073, 0.741531185599394440, 0.586087235467691130,
        0.405845151377397167, 0.207784955007898468, 0.0};
    static const double wk[8] = {0.022935322010529225, 0.063092092629978553,
        0.104790010322250184, 0.140653259715525919, 0.169004726639267903,
        0.190350578064785410, 0.204432940075298892, 0.209482141084727828};
    static const double wg[4] = {0.129484966168869693, 0.279705391489276668,
        0.381830050505118945, 0.417959183673469388};
    const double h = 0.5*(b - a), m = 0.5*(a + b);
    double k = wk[7]*f(m), g = wg[3]*f(m);
    for (int i = 0; i < 7; ++i)
    {
        const double s = f(m - h*xk[i]) + f(m + h*xk[i]);
        k += wk[i]*s;
        if (i % 2 == 1) g += wg[i/2]*s;
    }
    k *= h; g *= h;
    if ((depth >= 4 && std::fabs(k - g) <= tol) || depth > 40) return k;
    return gaussKronrod(f, a, m, 0.5*tol, depth + 1) + gaussKronrod(f, m, b, 0.5*tol, depth + 1);
}

double referenceVolume(const std::vector<vec3>& v, const std::vector<std::pair<int,int>>& e,
                       const vec3& c, double R)
{
    std::vector<double> zs = {-R, R};
    for (auto p : v) zs.push_back(std::max(-R, std::min(R, p.z - c.z)));
    // the slice area has kinks where the sphere meets an edge or is tangent
    // to a face plane: split the integral there too
    for (auto [i, j] : e)
    {
        const vec3 a = v[i] - c, d = v[j] - v[i];
        const double A = dot(d, d), B = 2*dot(a, d), C = dot(a, a) - R*R;
        const double disc = B*B - 4*A*C;
        if (disc < 0) continue;
        for (double s : {-1.0, 1.0})
        {
            const double t = (-B + s*std::sqrt(disc))/(2*A);
            if (t > 0 && t < 1) zs.push_back(a.z + t*d.z);
        }
    }
    for (std::size_t i = 0; i < v.size(); ++i)
        for (std::size_t j = i + 1; j < v.size(); ++j)
            for (std::size_t k = j + 1; k < v.size(); ++k)
            {
                vec3 n = cross(v[j] - v[i], v[k] - v[i]);
                if (mag(n) == 0) continue;
                n = (1.0/mag(n))*n;
                zs.push_back(R*n.z);
                zs.push_back(-R*n.z);
            }
    std::sort(zs.begin(), zs.end());
    const double tol = 1e-15*sphereVolume(R);
    double sum = 0;
    for (std::size_t k = 0; k + 1 < zs.size(); ++k)
    {
        if (zs[k + 1] <= zs[k]) continue;
        sum += gaussKronrod([&](double z)
            { return diskPolygonArea(std::sqrt(std::max(0.0, R*R - z*z)), slice(v, e, c, z)); },
            zs[k], zs[k + 1], tol, 0);
    }
    return sum;
}

struct polyhedron
{
    std::vector<vec3> v;
    std::vector<std::pair<int,int>> e;
    std::vector<std::vector<int>> f;   // right-hand order = outward normal
};

polyhedron box(vec3 lo, vec3 hi)
{
    polyhedron P;
    for (int k = 0; k < 8; ++k)
        P.v.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
    P.e = {{0,1},{2,3},{4,5},{6,7},{0,2},{1,3},{4,6},{5,7},{0,4},{1,5},{2,6},{3,7}};
    P.f = {{0,4,6,2},{1,3,7,5},{0,1,5,4},{2,6,7,3},{0,2,3,1},{4,5,7,6}};
    return P;
}

polyhedron tet(vec3 a, vec3 b, vec3 c, vec3 d)
{
    polyhedron P;
    if (dot(cross(b - a, c - a), d - a) < 0) std::swap(b, c);
    P.v = {a, b, c, d};
    P.e = {{0,1},{0,2},{0,3},{1,2},{1,3},{2,3}};
    P.f = {{0,2,1},{0,1,3},{0,3,2},{1,2,3}};
    return P;
}

double polyhedronVolume(const polyhedron& P, const vec3& c, double R)
{
    double v = 0;
    for (const auto& f : P.f)
    {
        auto pt = [&](std::size_t i) { return P.v[f[i]]; };
        vec3 n = cross(pt(1) - pt(0), pt(2) - pt(0));
        n = (1.0/mag(n))*n;
        v += polygonCone(c, R, pt, f.size(), n);
    }
    return v;
}

// The same through the caps of the faces (convex polyhedron): the ball when
// the centre is inside, else nothing, corrected face by face.
double polyhedronVolumeByCaps(const polyhedron& P, const vec3& c, double R)
{
    double v = 0;
    bool inside = true;
    for (const auto& f : P.f)
    {
        auto pt = [&](std::size_t i) { return P.v[f[i]]; };
        vec3 n = cross(pt(1) - pt(0), pt(2) - pt(0));
        n = (1.0/mag(n))*n;
        const double ds = dot(pt(0) - c, n);
        // on a face plane, inside or outside is a matter of round-off: the
        // cones decide there, as in the library
        if (std::fabs(ds) < 1e-9*R) return polyhedronVolume(P, c, R);
        inside = inside && ds > 0;
        v -= (ds > 0 ? 1 : -1)*polygonCap(c, R, pt, f.size(), n);
    }
    return inside ? v + sphereVolume(R) : v;
}
}

int main()
{
    const double R = 0.7;
    const double V = sphereVolume(R);
    const double tight = 1e-12*V;

    // closed forms: inside, centred on a face, an edge, a corner of a box
    const vec3 lo{-1, -1, -1}, hi{1, 1, 1};
    near("inside box", ballBoxVolume({0.1, -0.2, 0.05}, R, lo, hi), V, tight);
    near("centre on face", ballBoxVolume({1, 0, 0}, R, lo, hi), V/2, tight);
    near("centre on edge", ballBoxVolume({1, 1, 0}, R, lo, hi), V/4, tight);
    near("centre on corner", ballBoxVolume({1, 1, 1}, R, lo, hi), V/8, tight);
    near("cap", ballBoxVolume({0.6, 0, 0}, R, lo, hi), V - capVolume(R, 0.4), tight);
    near("cap closed form", capVolume(R, 0.4), 3.14159265358979323846*0.09*(2.1 - 0.3)/3, tight);
    near("touching face outside", ballBoxVolume({1.7, 0, 0}, R, lo, hi), 0, tight);
    near("general path corner", polyhedronVolume(box(lo, hi), {1, 1, 1}, R), V/8, tight);
    near("general path edge", polyhedronVolume(box(lo, hi), {1, 1, 0.3}, R), V/4, tight);
    // box much smaller than the sphere: the whole box
    near("box inside sphere", ballBoxVolume({0.05, 0, 0}, 3.0, lo, hi), 8, 1e-12*8);
    // tet corner: the solid angle of the trirectangular corner is pi/2
    near("tet corner", polyhedronVolume(tet({0,0,0},{2,0,0},{0,2,0},{0,0,2}), {0,0,0}, R),
         V/8, tight);

    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> U(-1, 1);
    double worstBox = 0, worstTet = 0, worstFast = 0, worstCaps = 0;
    for (int k = 0; k < 60; ++k)
    {
        // random boxes, some smaller than the sphere, centre anywhere near
        const vec3 a{U(rng), U(rng), U(rng)};
        const vec3 size{0.2 + 1.5*(U(rng) + 1), 0.2 + 1.5*(U(rng) + 1), 0.2 + 1.5*(U(rng) + 1)};
        const vec3 b = a + 0.5*size;
        const vec3 c{a.x + 1.2*U(rng), a.y + 1.2*U(rng), a.z + 1.2*U(rng)};
        const double ref = referenceVolume(box(a, b).v, box(a, b).e, c, R);
        worstBox = std::max(worstBox, std::fabs(polyhedronVolume(box(a, b), c, R) - ref)/V);
        worstFast = std::max(worstFast, std::fabs(ballBoxVolume(c, R, a, b) - ref)/V);

        const polyhedron T = tet({U(rng), U(rng), U(rng)}, {U(rng), U(rng), U(rng)},
                                 {U(rng), U(rng), U(rng)}, {U(rng), U(rng), U(rng)});
        const vec3 ct{0.8*U(rng), 0.8*U(rng), 0.8*U(rng)};
        const double refT = referenceVolume(T.v, T.e, ct, R);
        const double errT = std::fabs(polyhedronVolume(T, ct, R) - refT)/V;
        worstTet = std::max(worstTet, errT);
        worstCaps = std::max(worstCaps, std::fabs(polyhedronVolumeByCaps(box(a, b), c, R) - ref)/V);
        worstCaps = std::max(worstCaps, std::fabs(polyhedronVolumeByCaps(T, ct, R) - refT)/V);
    }
    near("random boxes and tets through the face caps vs integration", worstCaps, 0, 1e-12);
    std::printf("worst relative error through the caps %.2e\n", worstCaps);
    near("random boxes, general path vs integration (rel. to sphere)", worstBox, 0, 1e-12);
    near("random boxes, fast path vs integration (rel. to sphere)", worstFast, 0, 1e-12);
    near("random tets vs integration (rel. to sphere)", worstTet, 0, 1e-12);
    std::printf("worst relative errors: box %.2e, fast box %.2e, tet %.2e\n",
                worstBox, worstFast, worstTet);

    // partition of space: 27 boxes around the sphere and a box cut into 6 tets
    {
        const vec3 c{0.13, -0.07, 0.21};
        double sum = 0;
        for (int i = -1; i <= 1; ++i) for (int j = -1; j <= 1; ++j) for (int k = -1; k <= 1; ++k)
        {
            const vec3 l{i - 0.5, j - 0.5, k - 0.5};
            sum += ballBoxVolume(c, R, l, l + vec3{1, 1, 1});
        }
        near("27 small boxes sum to the sphere", sum, V, 1e-14*V);
        const polyhedron B = box({-0.3, -0.4, -0.2}, {0.5, 0.3, 0.6});
        const int t6[6][4] = {{0,1,3,7},{0,1,5,7},{0,4,5,7},{0,2,3,7},{0,2,6,7},{0,4,6,7}};
        double tsum = 0;
        for (auto& t : t6) tsum += polyhedronVolume(tet(B.v[t[0]], B.v[t[1]], B.v[t[2]], B.v[t[3]]), c, R);
        near("six tets sum to their box", tsum, ballBoxVolume(c, R, B.v[0], B.v[7]), 1e-14*V);
        // the same six tets through the caps, for centres inside, beside and
        // outside the box, and on the box's diagonal (on every tet's edge)
        for (const vec3 cc : {c, vec3{0.4, 0.2, 0.5}, vec3{0.9, -0.1, 0.3}, vec3{0.1, -0.05, 0.2}})
        {
            double csum = 0;
            for (auto& t : t6)
            {
                csum += polyhedronVolumeByCaps(tet(B.v[t[0]], B.v[t[1]], B.v[t[2]], B.v[t[3]]), cc, R);
            }
            near("six tets through the caps sum to their box", csum, ballBoxVolume(cc, R, B.v[0], B.v[7]), 1e-14*V);
        }
        near("cap of a face wholly over the disk",
             polygonCap(vec3{0.5, 0, 0}, R, [&](std::size_t i) { return box(lo, hi).v[box(lo, hi).f[1][i]]; },
                        4, {1, 0, 0}), capVolume(R, 0.5), 1e-15*V);
        // the foot of the centre on a face's vertex or edge (the angle there
        // is not 2 pi or 0), inside and outside the tet
        const polyhedron T = tet({0, 0, 0}, {2, 0, 0}, {0.5, 2, 0}, {0.7, 0.6, 2});
        for (const vec3 cc : {vec3{0.5, 2, 0.25}, vec3{0.5, 2, -0.25}, vec3{1, 0, 0.25}, vec3{1, 0, -0.25}})
        {
            near("caps: foot on a face's vertex or edge", polyhedronVolumeByCaps(T, cc, R),
                 polyhedronVolume(T, cc, R), 1e-13*V);
        }
    }
    // tangencies: a sphere touching a face, edge or corner from inside and outside
    for (double eps : {0.0, 1e-15, -1e-15, 1e-9})
    {
        near("tangent face inside", ballBoxVolume({1 - R - eps, 0, 0}, R, lo, hi),
             V - capVolume(R, R + eps), 1e-13*V);
        near("tangent face general", polyhedronVolume(box(lo, hi), {1 - R - eps, 0, 0}, R),
             V - capVolume(R, R + eps), 1e-13*V);
        near("centre near edge", polyhedronVolume(box(lo, hi), {1 + eps, 1 - eps, 0}, R),
             ballBoxVolume({1 + eps, 1 - eps, 0}, R, lo, hi), 1e-13*V);
        near("centre near corner", polyhedronVolume(box(lo, hi), {1 + eps, 1 + eps, 1 - eps}, R),
             V/8, 1e-8*V);
    }
    // sliver: a very thin box through the centre is its thickness times the disk area
    near("thin slab", ballBoxVolume({0, 0, 0}, R, {-2, -2, -1e-7}, {2, 2, 1e-7}),
         3.14159265358979323846*R*R*2e-7, 1e-9*3.14159265358979323846*R*R*2e-7);
    // wedge closed form and the plane split against the box formula
    {
        std::uniform_real_distribution<double> W(-1.1*R, 1.1*R);
        double worstWedge = 0, worstOctant = 0, worstSplit = 0, worstSum = 0;
        for (int k = 0; k < 2000; ++k)
        {
            const double a = W(rng), b = W(rng);
            const double ref = ballBoxVolume({0, 0, 0}, R, {a, b, -2*R}, {2*R, 2*R, 2*R});
            worstWedge = std::max(worstWedge, std::fabs(wedgeVolume(R, a, b) - ref)/V);
            const double c3 = W(rng);
            const double refO = ballBoxVolume({0, 0, 0}, R, {a, b, c3}, {2*R, 2*R, 2*R});
            worstOctant = std::max(worstOctant, std::fabs(octantVolume(R, a, b, c3) - refO)/V);
            const double p[3] = {W(rng), W(rng), W(rng)};
            const bool cut[3] = {k % 2 == 0, k % 3 != 0, k % 5 != 1};
            double piece[8];
            planeSplit(R, p, cut, piece);
            double sum = 0;
            for (int s = 0; s < 8; ++s)
            {
                sum += piece[s];
                vec3 lo{-2*R, -2*R, -2*R}, hi{2*R, 2*R, 2*R};
                double* l[3] = {&lo.x, &lo.y, &lo.z};
                double* h[3] = {&hi.x, &hi.y, &hi.z};
                bool empty = false;
                for (int d = 0; d < 3; ++d)
                {
                    if (!cut[d]) { empty |= bool(s & (1 << d)); continue; }
                    if (s & (1 << d)) *l[d] = p[d]; else *h[d] = p[d];
                }
                const double want = empty ? 0 : ballBoxVolume({0, 0, 0}, R, lo, hi);
                worstSplit = std::max(worstSplit, std::fabs(piece[s] - want)/V);
            }
            worstSum = std::max(worstSum, std::fabs(sum - V)/V);
        }
        std::printf("wedge worst %.2e, split worst %.2e, split sum worst %.2e\n",
                    worstWedge, worstSplit, worstSum);
        near("wedge closed form = box formula (rel. to sphere)", worstWedge, 0, 1e-14);
        near("octant closed form = box formula (rel. to sphere)", worstOctant, 0, 1e-14);
        std::printf("octant worst %.2e\n", worstOctant);
        near("plane split pieces = box formula (rel. to sphere)", worstSplit, 0, 1e-14);
        near("plane split pieces sum to the sphere", worstSum, 0, 1e-14);
        near("wedge through the centre is a quarter", wedgeVolume(R, 0, 0), V/4, 1e-15*V);
        // a plane just off the centre: the cone formula's arcsine of nearly 1
        // once lost 1e-12 here; reference by 30-digit quadrature (mpmath) of
        // the disk segments, for R = 1
        const double a = 0.85288064194891522, b = 5.3655017273168681e-05;
        const double exact = 0.03232562175975985279;
        near("wedge by a plane near the centre", wedgeVolume(1, a, b), exact, 1e-16);
        near("cone path by a plane near the centre",
             ballBoxVolume({0, 0, 0}, 1, {a, b, -2}, {2, 2, 2}), exact, 1e-15);
    }
    return testHarness::summary("geometry");
}
