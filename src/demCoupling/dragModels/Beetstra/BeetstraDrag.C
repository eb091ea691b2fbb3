#include "BeetstraDrag.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(Beetstra, 0);
    addToRunTimeSelectionTable(dragModel, Beetstra, dictionary);
}
}


Foam::scalar Foam::dragModels::Beetstra::beta
(
    const scalar d,
    const scalar Vp,
    const scalar alpha,
    const scalar magUr,
    const scalar rho,
    const scalar mu
) const
{
    const scalar phi = 1 - alpha;
    const scalar Rep = max(Re(d, alpha, magUr, rho, mu), SMALL);
    const scalar inertial =
        0.413*Rep/(24*sqr(alpha))
       *(1/alpha + 3*alpha*phi + 8.4*pow(Rep, -0.343))
       /(1 + pow(10.0, 3*phi)*pow(Rep, -0.5*(1 + 4*phi)));
    const scalar F =
        10*phi/sqr(alpha) + sqr(alpha)*(1 + 1.5*sqrt(phi)) + inertial;
    return 3*constant::mathematical::pi*mu*d*alpha*F;
}
