/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
// The four-at-a-time arctangent of the analytical wedge against std::atan2:
// error in units in the last place over the first quadrant (ratios from
// 1e-13 to 1e13 and uniform ones), the axes, the diagonal, the origin, the
// reduction's seams, and the plain path against the vector one.
#include "atanBatch.H"
#include "testHarness.H"

#include <cmath>
#include <random>

using testHarness::near;

namespace
{
double ulps(const double got, const double want)
{
    const double ulp = std::nextafter(want, 10.0) - want;
    return std::fabs(got - want)/ulp;
}
}

int main()
{
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> uniform(0, 1), logScale(-30, 30);

    double worstBatch = 0, worstPlain = 0, worstSeam = 0;
    for (int i = 0; i < 1000000; ++i)
    {
        double y[4], x[4], out[4];
        for (int j = 0; j < 4; ++j)
        {
            y[j] = (j % 2) ? uniform(rng) : std::exp(logScale(rng));
            x[j] = (j == 2) ? uniform(rng) : std::exp(logScale(rng));
        }
        atanBatch::atan2FirstQuadrant4(y, x, out);
        for (int j = 0; j < 4; ++j)
        {
            const double want = std::atan2(y[j], x[j]);
            worstBatch = std::max(worstBatch, ulps(out[j], want));
            worstPlain = std::max(worstPlain, ulps(atanBatch::atan2FirstQuadrant(y[j], x[j]), want));
        }
    }
    near("four at a time: worst error in ulp (4e6 samples)", worstBatch, 0, 4);
    near("one at a time: worst error in ulp (4e6 samples)", worstPlain, 0, 4);

    // either side of tan(pi/16), tan(3 pi/16) and 1, where the shift changes
    for (const double seam : {0.19891236737965800, 0.66817863791929891, 1.0})
    {
        for (int k = -50; k <= 50; ++k)
        {
            const double t = seam*(1 + k*1e-15);
            double y[4] = {t, 1, t*3, 2}, x[4] = {1, t, 3, 2*t}, out[4];
            atanBatch::atan2FirstQuadrant4(y, x, out);
            for (int j = 0; j < 4; ++j) worstSeam = std::max(worstSeam, ulps(out[j], std::atan2(y[j], x[j])));
        }
    }
    near("at the reduction's seams: worst error in ulp", worstSeam, 0, 4);

    double y[4] = {0, 1, 0, 2.5}, x[4] = {0, 0, 1, 2.5}, out[4];
    atanBatch::atan2FirstQuadrant4(y, x, out);
    near("atan2(0, 0) = 0", out[0], 0, 0);
    near("atan2(1, 0) = pi/2 exactly", out[1], std::atan2(1.0, 0.0), 0);
    near("atan2(0, 1) = 0", out[2], 0, 0);
    near("atan2(a, a) = pi/4 exactly", out[3], std::atan2(1.0, 1.0), 0);
    near("plain atan2(0, 0) = 0", atanBatch::atan2FirstQuadrant(0, 0), 0, 0);
    near("plain atan2(1, 0) = pi/2 exactly", atanBatch::atan2FirstQuadrant(1, 0), std::atan2(1.0, 0.0), 0);

    // in place (out aliasing y)
    double z[4] = {0.3, 2.0, 1e-9, 7.0}, w[4] = {1.0, 0.5, 1.0, 7e-12};
    double want[4];
    for (int j = 0; j < 4; ++j) want[j] = std::atan2(z[j], w[j]);
    atanBatch::atan2FirstQuadrant4(z, w, z);
    double worstInPlace = 0;
    for (int j = 0; j < 4; ++j) worstInPlace = std::max(worstInPlace, ulps(z[j], want[j]));
    near("in place: worst error in ulp", worstInPlace, 0, 4);

    return testHarness::summary("arctangent");
}
