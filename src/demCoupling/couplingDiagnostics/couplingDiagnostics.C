/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "couplingDiagnostics.H"

Foam::couplingDiagnostics::couplingDiagnostics()
:
    seconds_(Zero),
    worstMomentumError_(0),
    totalForce_(Zero),
    mostHeld_(0)
{}


void Foam::couplingDiagnostics::momentumBalance
(
    const vector& particlesGained,
    const vector& fluidLost
)
{
    const scalar error =
        mag(fluidLost - particlesGained)/max(mag(particlesGained), VSMALL);
    worstMomentumError_ = max(worstMomentumError_, error);
}


void Foam::couplingDiagnostics::log
(
    const label nCoupling,
    const mappingStatistics& s
)
{
    Info<< "coupling " << nCoupling << ": " << s.nParticles
        << " particles (at most " << mostHeld_ << " on a rank), seconds DEM " << seconds_[dem]
        << " exchange " << seconds_[exchange]
        << " voidFraction " << seconds_[voidFraction]
        << " forces " << seconds_[forces]
        << " fluid " << seconds_[fluid]
        << "; alpha " << s.minVoidFraction << ".." << s.maxVoidFraction
        << ", momentum balance " << worstMomentumError_
        << "; total fluid force on the particles " << totalForce_
        << "; wall seconds since the last coupling " << couplingClock_.timeIncrement() << endl;
    seconds_ = Zero;
    worstMomentumError_ = 0;
}
