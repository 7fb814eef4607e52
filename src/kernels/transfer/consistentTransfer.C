/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "consistentTransfer.H"

#include <stdexcept>

namespace c4f
{
namespace transfer
{

std::vector<double> consistentTransfer
(
    const std::vector<std::vector<int>>& faces,
    const std::vector<std::vector<double>>& weights,
    const std::vector<double>& values,
    const double outside
)
{
    if (faces.size() != weights.size())
    {
        throw std::invalid_argument
        (
            "consistentTransfer: faces and weights differ in size"
        );
    }

    std::vector<double> f(faces.size(), outside);
    for (std::size_t i = 0; i < faces.size(); ++i)
    {
        if (faces[i].size() != weights[i].size())
        {
            throw std::invalid_argument
            (
                "consistentTransfer: a face's indices and weights differ"
                " in size"
            );
        }
        if (faces[i].empty())
        {
            continue;
        }
        double s = 0;
        for (std::size_t k = 0; k < faces[i].size(); ++k)
        {
            const int j = faces[i][k];
            if (j < 0 || std::size_t(j) >= values.size())
            {
                throw std::invalid_argument
                (
                    "consistentTransfer: master face index out of range"
                );
            }
            s += weights[i][k]*values[j];
        }
        f[i] = s;
    }
    return f;
}

} // End namespace transfer
} // End namespace c4f
