/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "selfContactFilter.H"

#include <algorithm>

c4f::search::SelfContactFilter::SelfContactFilter
(
    const std::vector<std::vector<int>>& faces
)
{
    int nPoints = 0;
    for (const std::vector<int>& f : faces)
    {
        for (const int p : f)
        {
            nPoints = std::max(nPoints, p + 1);
        }
    }
    pointFaces_.resize(nPoints);
    for (size_t j = 0; j < faces.size(); ++j)
    {
        for (const int p : faces[j])
        {
            if (p >= 0)
            {
                pointFaces_[p].push_back(int(j));
            }
        }
    }
}


std::vector<int> c4f::search::SelfContactFilter::facesAround
(
    const std::vector<int>& points
) const
{
    std::vector<int> around;
    for (const int p : points)
    {
        if (p >= 0 && p < int(pointFaces_.size()))
        {
            around.insert
            (
                around.end(), pointFaces_[p].begin(), pointFaces_[p].end()
            );
        }
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    return around;
}


bool c4f::search::SelfContactFilter::excluded
(
    const std::vector<int>& aroundSlave,
    const Eigen::Vector3d& ns,
    const int j,
    const Eigen::Vector3d& nm
)
{
    // Strictly the same way: faces at right angles (a slot's end and its
    // sides) may still be pairs where a body folds into a corner
    if (ns.dot(nm) > 0)
    {
        return true;
    }
    return std::binary_search(aroundSlave.begin(), aroundSlave.end(), j);
}


bool c4f::search::SelfContactFilter::behindUnfaced
(
    const Eigen::Vector3d& ns,
    const Eigen::Vector3d& nm,
    const double g
)
{
    return g < 0 && ns.dot(nm) > -minFacing;
}


bool c4f::search::SelfContactFilter::slaveOfPair
(
    const Eigen::Vector3d& ns,
    const Eigen::Vector3d& nm
)
{
    static const Eigen::Vector3d e(Eigen::Vector3d(1, 2, 3).normalized());
    return (ns - nm).dot(e) < pairBand;
}
