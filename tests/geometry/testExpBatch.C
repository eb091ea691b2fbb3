/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
// The batch exponential of the kernel model against std::exp: relative
// error over the range the kernel uses and beyond, the ends of the range,
// NaN, and a batch whose length is not a whole number of vectors.
#include "expBatch.H"
#include "testHarness.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using testHarness::near;

int main()
{
    std::mt19937_64 rng(11);

    // relative error, sampled densely where Gaussians live and over the
    // whole range down to -700
    double worstKernel = 0, worstRange = 0;
    std::uniform_real_distribution<double> kernelArgs(-40, 0), rangeArgs(-700, 0);
    for (int i = 0; i < 2000000; ++i)
    {
        const double a = kernelArgs(rng), b = rangeArgs(rng);
        worstKernel = std::max(worstKernel, std::fabs(expBatch::expNonPositive(a)/std::exp(a) - 1));
        worstRange = std::max(worstRange, std::fabs(expBatch::expNonPositive(b)/std::exp(b) - 1));
    }
    near("relative error on [-40, 0] (2e6 samples)", worstKernel, 0, 1e-15);
    near("relative error on [-700, 0] (2e6 samples)", worstRange, 0, 1e-15);

    // the ends and the reduction's seams: exactly 1 at 0, multiples of ln 2
    near("exp(0) = 1 exactly", expBatch::expNonPositive(0.0), 1, 0);
    near("exp(-0) = 1 exactly", expBatch::expNonPositive(-0.0), 1, 0);
    near("exp(-1e-300) = 1", expBatch::expNonPositive(-1e-300), 1, 0);
    double worstSeam = 0;
    for (int k = 1; k < 1000; ++k)
    {
        for (const double eps : {-1e-12, 0.0, 1e-12})
        {
            const double x = -k*0.6931471805599453 + eps;
            if (x > 0 || x < -700) continue;
            worstSeam = std::max(worstSeam, std::fabs(expBatch::expNonPositive(x)/std::exp(x) - 1));
        }
    }
    near("relative error at k ln 2 (k < 1000)", worstSeam, 0, 1e-15);
    near("exp(-700.5) = 0 (below the range)", expBatch::expNonPositive(-700.5), 0, 0);
    near("exp(-1e300) = 0", expBatch::expNonPositive(-1e300), 0, 0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    testHarness::check(std::isnan(expBatch::expNonPositive(nan)), "NaN stays NaN", 0, 0, 0);

    // batches of every length up to 19, in place and not: element by
    // element equal to the scalar function
    double worstBatch = 0;
    for (int n = 0; n < 20; ++n)
    {
        std::vector<double> x(n), y(n), z(n);
        for (double& v : x) v = kernelArgs(rng);
        expBatch::expNonPositive(x.data(), y.data(), n);
        z = x;
        expBatch::expNonPositive(z.data(), z.data(), n);
        for (int i = 0; i < n; ++i)
        {
            worstBatch = std::max(worstBatch, std::fabs(y[i]/std::exp(x[i]) - 1));
            worstBatch = std::max(worstBatch, std::fabs(z[i]/std::exp(x[i]) - 1));
        }
    }
    near("batches of 0 to 19 values against std::exp", worstBatch, 0, 1e-15);

    // expClamped: either sign within the bound, the bound beyond it, and
    // batches against the scalar function
    double worstClamped = 0, worstClampedBatch = 0;
    std::uniform_real_distribution<double> signedArgs(-700, 700);
    for (int i = 0; i < 2000000; ++i)
    {
        const double a = signedArgs(rng);
        worstClamped = std::max(worstClamped, std::fabs(expBatch::expClamped(a, 700)/std::exp(a) - 1));
    }
    near("expClamped: relative error on [-700, 700] (2e6 samples)", worstClamped, 0, 1e-15);
    near("expClamped(0) = 1 exactly", expBatch::expClamped(0.0, 150), 1, 0);
    near("expClamped(200, 150) = exp(150)", expBatch::expClamped(200.0, 150)/std::exp(150.0), 1, 1e-15);
    near("expClamped(-1e300, 150) = exp(-150)", expBatch::expClamped(-1e300, 150)/std::exp(-150.0), 1, 1e-15);
    near("expClamped(1e300, 700) is finite: exp(700)", expBatch::expClamped(1e300, 700)/std::exp(700.0), 1, 1e-15);
    for (int n = 0; n < 20; ++n)
    {
        std::vector<double> x(n), y(n);
        for (double& v : x) v = signedArgs(rng)*0.3;
        expBatch::expClamped(x.data(), y.data(), n, 150);
        for (int i = 0; i < n; ++i)
        {
            const double want = std::exp(std::min(std::max(x[i], -150.0), 150.0));
            worstClampedBatch = std::max(worstClampedBatch, std::fabs(y[i]/want - 1));
        }
    }
    near("expClamped batches of 0 to 19 values (bound 150) against std::exp", worstClampedBatch, 0, 1e-15);

    return testHarness::summary("exponential");
}
