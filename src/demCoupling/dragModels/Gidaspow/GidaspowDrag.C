#include "GidaspowDrag.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(Gidaspow, 0);
    addToRunTimeSelectionTable(dragModel, Gidaspow, dictionary);
}
}


Foam::scalar Foam::dragModels::Gidaspow::beta
(
    const scalar d,
    const scalar Vp,
    const scalar alpha,
    const scalar magUr,
    const scalar rho,
    const scalar mu
) const
{
    if (alpha < 0.8)
    {
        return Vp*(150*(1 - alpha)*mu/(alpha*d*d) + 1.75*rho*magUr/d);
    }
    // Cd |Ur| written so that it stays finite as the slip vanishes
    const scalar Rep = Re(d, alpha, magUr, rho, mu);
    const scalar CdMagUr =
        Rep < 1000
      ? 24*mu/(alpha*rho*d)*(1 + 0.15*pow(Rep, 0.687))
      : 0.44*magUr;
    return Vp*0.75*CdMagUr*rho/d*pow(alpha, -1.65);
}
