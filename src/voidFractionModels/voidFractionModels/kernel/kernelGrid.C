/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
// The kernel on tensor grids: per-direction windows and Gaussian factors,
// fixed windows and batched exponentials on uniform planes.

#include "kernel.H"
#include "kernelConstants.H"
#include "expBatch.H"

namespace
{
// Uniform planes g (1/spacing inv): the first cell and the number of cells
// whose centres, at g0 + (k + 1/2) h, lie within rc of x; by arithmetic,
// widened by round-off (the ball test of ballRows is the exact one)
inline Foam::label uniformWindow
(
    const Foam::scalarList& g,
    const Foam::scalar inv,
    const Foam::scalar x,
    const Foam::scalar rc,
    Foam::label& first
)
{
    const Foam::scalar lo = (x - rc - g.first())*inv - 0.5 - Foam::kernelConstants::planeTolerance;
    const Foam::scalar hi = (x + rc - g.first())*inv - 0.5 + Foam::kernelConstants::planeTolerance;
    first = (lo <= 0) ? 0 : Foam::label(lo) + 1;
    const Foam::label end = (hi < 0) ? 0 : Foam::min(Foam::label(hi) + 1, g.size() - 1);
    return Foam::max(end - first, Foam::label(0));
}

// Tensor grids: the cells of the window inside the ball of radius
// sqrt(rc2), written from cells and fractions on;
// their number returned, their weights added to sum. Inlined into both
// callers: the compiler then sees the arrays are not the rows. NX, NY, NZ:
// the window sizes when fixed at compile time (0: n).
//- The cells of a tensor grid's window around one particle: first index
//  and size per direction, each cell's factor and squared distance per
//  direction, and the squared reach
struct ballWindow
{
    const Foam::particleCellLocator& locator;
    const Foam::label* first;
    const Foam::label* n;
    const Foam::scalar* factor[3];
    const Foam::scalar* distSqr[3];
    Foam::scalar rc2;
};

template<int NX = 0, int NY = 0, int NZ = 0>
inline Foam::label ballRows
(
    const ballWindow& w,
    Foam::label* cells,
    Foam::scalar* fractions,
    Foam::scalar& sum
)
{
    const Foam::label* n = w.n;
    const Foam::scalar *fx = w.factor[0], *fy = w.factor[1], *fz = w.factor[2];
    const Foam::scalar *dx = w.distSqr[0], *dy = w.distSqr[1], *dz = w.distSqr[2];
    Foam::label m = 0;
    for (Foam::label kz = 0; kz < (NZ ? NZ : n[2]); ++kz)
    {
        for (Foam::label ky = 0; ky < (NY ? NY : n[1]); ++ky)
        {
            // every cell of the row is written and only those in the ball
            // are kept, and their weights added as a product (a choice
            // compiled to a branch): no branch on the data, whose outcome
            // the branch predictor cannot know
            const Foam::scalar left = w.rc2 - (dy[ky] + dz[kz]);
            const Foam::scalar fyz = fy[ky]*fz[kz];
            const Foam::label* row = w.locator.gridRow(w.first[0], w.first[1] + ky, w.first[2] + kz);
            for (Foam::label kx = 0; kx < (NX ? NX : n[0]); ++kx)
            {
                const Foam::scalar f = fx[kx]*fyz;
                const bool inside = dx[kx] <= left;
                cells[m] = row[kx];
                fractions[m] = f;
                sum += f*Foam::scalar(inside);
                m += inside;
            }
        }
    }
    return m;
}
}



Foam::label Foam::voidFractionModels::kernel::axisWindow
(
    const direction d,
    const scalar x,
    const scalar rc,
    label& first
) const
{
    const scalarList& g = locator().gridPlanes(d);
    if (x + rc < g.first() || x - rc > g.last())
    {
        first = 0;
        return 0;
    }
    const scalar inv = locator().invSpacing(d);
    if (inv > 0) return uniformWindow(g, inv, x, rc, first);

    // the intervals holding the ends of the reach, then the centres
    const scalarList& xc = gridCentres_[d];
    const scalar from = max(x - rc, g.first());
    const scalar to = min(x + rc, g.last());
    first = locator().interval(d, from);
    first += (xc[first] < from);
    label end = locator().interval(d, to) + 1;
    end -= (xc[end - 1] > to);
    return max(end - first, label(0));
}


void Foam::voidFractionModels::kernel::axisFactors
(
    const scalar x[3],
    const scalar b,
    const scalar rc,
    const axisMirrors& mirrors,
    axisWindows& w
)
{
    label n[3];
    label total = 0;
    for (direction d = 0; d < 3; ++d)
    {
        n[d] = axisWindow(d, x[d], rc, w.first[d]);
        total += n[d]*(1 + mirrors.n[d]);
    }
    const scalar invB2 = 1/sqr(b);

    // all Gaussians of the particle in one call, padded to whole vectors
    // of four: the values are few, so only together do they fill them
    exponents_.setSize((total + 3)/4*4);
    scalar* e = exponents_.data();
    for (direction d = 0; d < 3; ++d)
    {
        w.distSqr[d].setSize(n[d]);
        scalar* dd = w.distSqr[d].data();
        const scalar* xi = gridCentres_[d].cdata() + w.first[d];
        const FixedList<scalar, 2>& m = mirrors.at[d];
        for (label k = 0; k < n[d]; ++k)
        {
            dd[k] = sqr(xi[k] - x[d]);
            *e++ = gaussianArgument(dd[k], invB2);
            for (label j = 0; j < mirrors.n[d]; ++j) *e++ = gaussianArgument(sqr(xi[k] - m[j]), invB2);
        }
    }
    for (label i = total; i < exponents_.size(); ++i) *e++ = 0;
    expBatch::expNonPositive(exponents_.cdata(), exponents_.data(), exponents_.size());

    const scalar* gauss = exponents_.cdata();
    for (direction d = 0; d < 3; ++d)
    {
        w.factor[d].setSize(n[d]);
        scalar* f = w.factor[d].data();
        const scalar* h = gridWidths_[d].cdata() + w.first[d];
        for (label k = 0; k < n[d]; ++k)
        {
            scalar sum = *gauss++;
            for (label j = 0; j < mirrors.n[d]; ++j) sum += *gauss++;
            f[k] = h[k]*sum;
        }
    }
}


inline void Foam::voidFractionModels::kernel::finishRow
(
    const label p,
    const label k0,
    const label m,
    const scalar sum
)
{
    // nothing positive here: the row keeps the centre cell alone, at 0.
    // Whether the particle reached any centre is known only once its sums
    // are combined over the ranks and images that hold it, so the slot is
    // kept now, while the row is open, and distribute's normalisation sets
    // it to 1 if the combined sum is 0
    rows().truncateEntries(sum > 0 ? k0 + m : k0);
    if (sum == 0 && centreCells()[p] >= 0) rows().append(centreCells()[p], 0);
    sums_[p] = sum;
}


void Foam::voidFractionModels::kernel::prepareBlock
(
    const UList<point>& x,
    const label p0,
    const label p1,
    const bool relative
)
{
    // the windows of a block of particles and the arguments of all their
    // exponentials, which then run in one batch: a particle's few values
    // alone would leave the batch waiting on its latency; room for every
    // particle's twelve Gaussians and three mirrors' twelve
    block_.setSize(p1 - p0);
    blockArgs_.setSize(kernelConstants::argsPerParticle*(p1 - p0));
    scalar* const args = blockArgs_.data();
    label nArgs = 0;
    for (label p = p0; p < p1; ++p)
    {
        windowEntry& W = block_[p - p0];
        W.fixed = false;
        if (b_[p] <= 0) continue;
        const point& c = x[p];
        const scalar rc = cutoff_*b_[p];
        const scalar invB2 = 1/sqr(b_[p]);
        const axisMirrors mirrors = findMirrors(c, centreCells()[p], rc);
        const scalar* xc[3];
        bool fits = true;
        for (direction d = 0; d < 3; ++d)
        {
            const scalarList& g = locator().gridPlanes(d);
            W.n[d] = uniformWindow(g, locator().invSpacing(d), c[d], rc, W.first[d]);
            fits = fits && W.n[d] <= kernelConstants::windowCells;
            // an empty window beyond the grid: read its last cell and the
            // three padded ones after it, never past them
            W.first[d] = min(W.first[d], g.size() - 2);
            xc[d] = gridCentres_[d].cdata() + W.first[d];
            for (label k = 0; k < 4; ++k) W.dist[4*d + k] = sqr(xc[d][k] - c[d]);
            W.nMirrors[d] = mirrors.n[d];
        }
        if (!fits) continue;
        W.fixed = true;
        W.factorised =
            factorised_ && relative && !(mirrors.n[0] || mirrors.n[1] || mirrors.n[2]);
        W.rc = rc;
        W.arg = nArgs;
        if (W.factorised)
        {
            // exp(-(d0 + k h)^2/b^2) = exp(-d0^2/b^2) R^k C^(k^2), d0 the
            // first centre's offset, R = exp(-2 d0 h/b^2), C = exp(-h^2/b^2):
            // the first factor is every cell's and cancels in the
            // normalisation of a whole particle (where ranks or images
            // share one, their windows' first cells differ)
            for (direction d = 0; d < 3; ++d)
            {
                args[nArgs++] = -2*(xc[d][0] - c[d])*spacing_[d]*invB2;
                args[nArgs++] = -sqr(spacing_[d])*invB2;
            }
            continue;
        }
        for (direction d = 0; d < 3; ++d)
        {
            for (label k = 0; k < 4; ++k) args[nArgs++] = gaussianArgument(W.dist[4*d + k], invB2);
            for (label j = 0; j < mirrors.n[d]; ++j)
            {
                for (label k = 0; k < 4; ++k)
                {
                    args[nArgs++] = gaussianArgument(sqr(xc[d][k] - mirrors.at[d][j]), invB2);
                }
            }
        }
    }
    // the clamp keeps the factorised products finite (kernelConstants.H)
    expBatch::expClamped
    (
        args, args, nArgs,
        factorised_ ? kernelConstants::factorisedArgLimit : kernelConstants::argLimit
    );
}


bool Foam::voidFractionModels::kernel::blockRows(const label p, const label p0)
{
    const windowEntry& W = block_[p - p0];
    if (!W.fixed) return false;

    // four cells per direction whatever the window holds: fixed loops over
    // local arrays; the cells beyond a shorter window are never read
    scalar e[12];
    const scalar* a = blockArgs_.cdata() + W.arg;
    for (direction d = 0; d < 3; ++d)
    {
        scalar* f = e + 4*d;
        if (W.factorised)
        {
            // the cells' volume, the same in every cell of uniform planes,
            // cancels in the normalisation like the first cell's Gaussian
            const scalar RC = a[2*d]*a[2*d + 1];
            const scalar C2 = sqr(a[2*d + 1]);
            f[0] = 1;
            f[1] = RC;
            f[2] = RC*RC*C2;
            f[3] = f[2]*RC*sqr(C2);
            continue;
        }
        for (label k = 0; k < 4; ++k) f[k] = a[k];
        a += 4;
        for (label j = 0; j < W.nMirrors[d]; ++j, a += 4)
        {
            for (label k = 0; k < 4; ++k) f[k] += a[k];
        }
        // each cell's own width: the planes are uniform to round-off only
        const scalar* h = gridWidths_[d].cdata() + W.first[d];
        for (label k = 0; k < 4; ++k) f[k] *= h[k];
    }

    const label k0 = rows().extend(W.n[0]*W.n[1]*W.n[2]);
    scalar sum = 0;
    label* cells = rows().cellsData() + k0;
    scalar* fractions = rows().fractionsData() + k0;
    const ballWindow window
    {
        locator(), W.first, W.n, {e, e + 4, e + 8}, {W.dist, W.dist + 4, W.dist + 8}, sqr(W.rc)
    };

    // windows of two or three cells per direction (those of the default
    // bandwidth) in loops of fixed length: one choice among eight instead
    // of a loop end per row, which the branch predictor cannot know
    const unsigned twos = (W.n[0] == 2) | (W.n[1] == 2) << 1 | (W.n[2] == 2) << 2;
    const unsigned threes = (W.n[0] == 3) | (W.n[1] == 3) << 1 | (W.n[2] == 3) << 2;
    label m = 0;
    if ((twos | threes) != 7) m = ballRows<>(window, cells, fractions, sum);
    else switch (twos)
    {
        case 0: m = ballRows<3, 3, 3>(window, cells, fractions, sum); break;
        case 1: m = ballRows<2, 3, 3>(window, cells, fractions, sum); break;
        case 2: m = ballRows<3, 2, 3>(window, cells, fractions, sum); break;
        case 3: m = ballRows<2, 2, 3>(window, cells, fractions, sum); break;
        case 4: m = ballRows<3, 3, 2>(window, cells, fractions, sum); break;
        case 5: m = ballRows<2, 3, 2>(window, cells, fractions, sum); break;
        case 6: m = ballRows<3, 2, 2>(window, cells, fractions, sum); break;
        default: m = ballRows<2, 2, 2>(window, cells, fractions, sum); break;
    }
    finishRow(p, k0, m, sum);
    return true;
}


void Foam::voidFractionModels::kernel::gridWeights
(
    const label p,
    const point& c,
    const scalar b,
    const scalar rc,
    const axisMirrors& mirrors
)
{
    const scalar x[3] = {c.x(), c.y(), c.z()};
    axisWindows& w = windows_;
    axisFactors(x, b, rc, mirrors, w);
    const label n[3] = {w.factor[0].size(), w.factor[1].size(), w.factor[2].size()};

    // room for the whole box of cells; the ball keeps about half of it
    const label k0 = rows().extend(n[0]*n[1]*n[2]);
    scalar sum = 0;
    const ballWindow window
    {
        locator(), w.first, n,
        {w.factor[0].cdata(), w.factor[1].cdata(), w.factor[2].cdata()},
        {w.distSqr[0].cdata(), w.distSqr[1].cdata(), w.distSqr[2].cdata()}, sqr(rc)
    };
    const label m = ballRows<>(window, rows().cellsData() + k0, rows().fractionsData() + k0, sum);
    finishRow(p, k0, m, sum);
}


