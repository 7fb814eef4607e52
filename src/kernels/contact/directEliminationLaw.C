/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "directEliminationLaw.H"

namespace c4f
{
namespace contact
{

bool directEliminationActive
(
    const bool eliminated,
    const double reaction,
    const double gap
)
{
    // Comparisons with NaN are false: such a face is not constrained
    return eliminated ? reaction > 0 : gap < 0;
}

} // End namespace contact
} // End namespace c4f
