/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactConstraintGroups.H"
#include "vector2DField.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::contactConstraintGroups::side>
Foam::contactConstraintGroups::sideNames
({
    { side::slave, "slave" },
    { side::master, "master" },
    { side::automatic, "auto" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactConstraintGroups::contactConstraintGroups
(
    const contactPair& pair,
    const side s,
    const int tag
)
:
    pair_(pair),
    side_(s),
    tag_(tag),
    any_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactConstraintGroups::set
(
    const labelUList& masterFace,
    const scalarUList& area,
    const scalarUList& kappa,
    const scalarUList& slaveR,
    const scalarField& masterR
)
{
    masterFace_ = masterFace;
    area_ = area;
    grouped_.setSize(masterFace.size());
    grouped_ = false;
    any_ = false;

    const label nMaster = masterR.size();
    kbar_.setSize(nMaster);
    kbar_ = 0;
    kbarByArea_.setSize(nMaster);
    kbarByArea_ = 0;

    if (side_ == side::slave)
    {
        return;
    }

    // Per master face, over processors: A_j, sum_s A_s/kappa_s and
    // sum_s A_s delta_i/K_i
    Field<vector> sums(nMaster, Zero);
    forAll(masterFace, s)
    {
        sums[masterFace[s]] +=
            area[s]*vector(1, 1/kappa[s], slaveR[s]);
    }
    sums = pair_.sumOverProcessors(sums, tag_);

    boolList groupedFace(nMaster, false);
    forAll(sums, j)
    {
        const scalar A = sums[j].x();
        if (A > 0)
        {
            groupedFace[j] =
                side_ == side::master
             || sums[j].z()/A < stiffRatio_*masterR[j];
            if (groupedFace[j])
            {
                kbar_[j] = A/sums[j].y();
                kbarByArea_[j] = kbar_[j]/A;
                any_ = true;
            }
        }
    }

    forAll(masterFace, s)
    {
        grouped_[s] = groupedFace[masterFace[s]];
    }
}


Foam::label Foam::contactConstraintGroups::nGroups() const
{
    label n = 0;
    for (const scalar k : kbar_)
    {
        n += (k > 0);
    }
    return n;
}


Foam::tmp<Foam::scalarField> Foam::contactConstraintGroups::constraintGap
(
    const scalarField& gap,
    const boolList& coupled,
    boolList& groupedFace
) const
{
    tmp<scalarField> tcg(new scalarField(gap));
    groupedFace.setSize(gap.size());
    groupedFace = false;
    if (!any_)
    {
        return tcg;
    }
    scalarField& cg = tcg.ref();

    const labelListList& faces = pair_.overlapFaces();
    const List<scalarList>& weights = pair_.overlapWeights();
    const List<scalarList>& gaps = pair_.overlapGaps();
    const scalarField& magSf = pair_.slavePatch().magSf();

    // Per gathered master face, over processors: sum_s A_s g_s and A_j
    Field<vector2D> sums(kbar_.size(), Zero);
    forAll(faces, i)
    {
        if (i < coupled.size() && coupled[i])
        {
            forAll(faces[i], k)
            {
                const label j = faces[i][k];
                if (kbar_[j] > 0)
                {
                    const scalar A = weights[i][k]*magSf[i];
                    sums[j] += vector2D(A*gaps[i][k], A);
                }
            }
        }
    }
    sums = pair_.sumOverProcessors(sums, tag_);

    // A face that is not coupled is not constrained: its own gap
    forAll(faces, i)
    {
        if (i >= coupled.size() || !coupled[i])
        {
            continue;
        }
        scalar sumW = 0;
        scalar sumWg = 0;
        bool grouped = false;
        forAll(faces[i], k)
        {
            const label j = faces[i][k];
            const scalar w = weights[i][k];
            sumW += w;
            if (kbar_[j] > 0 && sums[j].y() > 0)
            {
                sumWg += w*sums[j].x()/sums[j].y();
                grouped = true;
            }
            else
            {
                sumWg += w*gap[i];
            }
        }
        if (grouped && sumW > 0)
        {
            cg[i] = sumWg/sumW;
            groupedFace[i] = true;
        }
    }
    return tcg;
}


// ************************************************************************* //
