/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactInterfaceCoupling.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::contactInterfaceCoupling::masterCellValues
(
    const UList<Type>& cellValues
) const
{
    const labelUList& fc = pair_.masterPatch().faceCells();
    Field<Type> local(fc.size());
    forAll(fc, facei)
    {
        local[facei] = cellValues[fc[facei]];
    }
    return pair_.gatherMaster(local, tag_);
}


Foam::vector Foam::contactInterfaceCoupling::implicitWeights(const vector& n)
{
    const scalar n1 = mag(n.x()) + mag(n.y()) + mag(n.z());
    return n1*cmptMag(n);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactInterfaceCoupling::contactInterfaceCoupling
(
    const contactPatchPair& pair
)
:
    pair_(pair),
    start_(1, 0),
    nMaster_(0),
    hasLaw_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactInterfaceCoupling::set(const inputs& in)
{
    const fvPatch& slave = pair_.slavePatch();
    const scalarField& magS = slave.magSf();
    const labelListList& faces = pair_.overlapFaces();
    const List<scalarList>& weights = pair_.overlapWeights();

    // The last solve's law at the current state, for the deferred
    // correction (nothing before the first solve)
    labelList oldStart, oldMaster;
    scalarList oldP, oldCoeff;
    scalarField oldFaceP(slave.size(), 0);
    vectorField oldTM;
    if (in.D && hasLaw_)
    {
        const vectorField& D = *in.D;
        const labelUList& fc = slave.faceCells();
        const vectorField DM(masterCellValues(D));

        oldP.setSize(coeff_.size());
        vectorField FM(nMaster_, Zero);
        forAll(normal_, i)
        {
            const vector& n = normal_[i];
            vector F(explicitForce_[i]);
            for (label s = start_[i]; s < start_[i+1]; ++s)
            {
                oldP[s] =
                    coeff_[s]/area_[s]
                   *(((DM[masterFace_[s]] - D[fc[i]]) & n) + offset_[s]);
                F += area_[s]*oldP[s]*n;
            }
            oldFaceP[i] = (F & n)/magS[i];
            forAll(faces[i], k)
            {
                FM[faces[i][k]] -= weights[i][k]*F;
            }
        }
        oldTM = pair_.sumOverProcessors(FM, tag_)()/in.masterMagSf;
        oldStart.transfer(start_);
        oldMaster.transfer(masterFace_);
        oldCoeff.transfer(coeff_);
    }

    nMaster_ = pair_.nMasterFaces();
    normal_ = in.normal;
    explicitForce_.setSize(slave.size());

    DynamicList<label> start(slave.size() + 1);
    DynamicList<label> mf;
    DynamicList<scalar> coeff;
    DynamicList<scalar> offset;
    DynamicList<scalar> area;
    start.append(0);

    forAll(faces, i)
    {
        const vector& n = in.normal[i];
        explicitForce_[i] = Zero;

        if (!in.coupled[i])
        {
            explicitForce_[i] = in.pressure0[i]*n*magS[i];
        }
        else
        {
            // The gap linearised about the current face displacements
            vector Dm(Zero);
            forAll(faces[i], k)
            {
                Dm += weights[i][k]*in.masterDf[faces[i][k]];
            }
            const scalar gRef = in.gap[i] - (n & (in.slaveDf[i] - Dm));

            const scalar rs = in.slaveDelta[i]/in.slaveK[i];
            forAll(faces[i], k)
            {
                const label j = faces[i][k];
                const scalar rm = in.masterDelta[j]/in.masterK[j];
                const scalar kij = 1/(rs + rm + in.compliance[i]);

                mf.append(j);
                area.append(weights[i][k]*magS[i]);
                coeff.append(area.last()*kij);
                offset.append
                (
                   -gRef
                  + rs*(in.slaveC[i] & n)
                  - rm*(in.masterC[j] & n)
                  + in.compliance[i]*in.pressure0[i]
                );
            }
        }
        start.append(mf.size());
    }

    start_.transfer(start);
    masterFace_.transfer(mf);
    coeff_.transfer(coeff);
    offset_.transfer(offset);
    area_.transfer(area);
    hasLaw_ = true;

    // The deferred correction, from the last solve's law at the current
    // state: its sub-face pressures and master tractions
    if (oldTM.size())
    {
        forAll(normal_, i)
        {
            const vector& n = normal_[i];
            for (label s = start_[i]; s < start_[i+1]; ++s)
            {
                const label j = masterFace_[s];

                // The old sub-face of the same pair, else the face's mean
                scalar pOld = oldFaceP[i];
                for (label o = oldStart[i]; o < oldStart[i+1]; ++o)
                {
                    if (oldMaster[o] == j)
                    {
                        pOld = oldP[o];
                        break;
                    }
                }
                offset_[s] +=
                    in.masterDelta[j]/in.masterK[j]*((oldTM[j] & n) + pOld);
            }
        }
    }
}


Foam::tmp<Foam::vectorField> Foam::contactInterfaceCoupling::slaveDiag() const
{
    tmp<vectorField> td(new vectorField(normal_.size(), Zero));
    vectorField& d = td.ref();
    forAll(d, i)
    {
        const vector w(implicitWeights(normal_[i]));
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            d[i] += coeff_[s]*w;
        }
    }
    return td;
}


Foam::tmp<Foam::vectorField> Foam::contactInterfaceCoupling::masterDiag() const
{
    vectorField d(nMaster_, Zero);
    forAll(normal_, i)
    {
        const vector w(implicitWeights(normal_[i]));
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            d[masterFace_[s]] += coeff_[s]*w;
        }
    }
    return pair_.masterSlice(pair_.sumOverProcessors(d, tag_)());
}


Foam::tmp<Foam::scalarField> Foam::contactInterfaceCoupling::slaveNeighbour
(
    const UList<solveScalar>& psi,
    const direction cmpt
) const
{
    const scalarField psiM(masterCellValues(psi));

    tmp<scalarField> tnb(new scalarField(normal_.size(), 0));
    scalarField& nb = tnb.ref();
    forAll(nb, i)
    {
        const scalar w = implicitWeights(normal_[i])[cmpt];
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            nb[i] += coeff_[s]*w*psiM[masterFace_[s]];
        }
    }
    return tnb;
}


Foam::tmp<Foam::scalarField> Foam::contactInterfaceCoupling::masterNeighbour
(
    const UList<solveScalar>& psi,
    const direction cmpt
) const
{
    const labelUList& fc = pair_.slavePatch().faceCells();

    scalarField nb(nMaster_, 0);
    forAll(normal_, i)
    {
        const scalar w = implicitWeights(normal_[i])[cmpt];
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            nb[masterFace_[s]] += coeff_[s]*w*psi[fc[i]];
        }
    }
    return pair_.masterSlice(pair_.sumOverProcessors(nb, tag_)());
}


void Foam::contactInterfaceCoupling::forces
(
    const vectorField& D,
    vectorField& slaveForce,
    vectorField& masterForce,
    scalarField& slavePressure
) const
{
    const fvPatch& slave = pair_.slavePatch();
    const labelUList& fc = slave.faceCells();
    const vectorField DM(masterCellValues(D));
    const labelListList& faces = pair_.overlapFaces();
    const List<scalarList>& weights = pair_.overlapWeights();

    slaveForce.setSize(normal_.size());
    slavePressure.setSize(normal_.size());
    vectorField FM(nMaster_, Zero);

    forAll(normal_, i)
    {
        const vector& n = normal_[i];
        vector F(explicitForce_[i]);
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            F += coeff_[s]*(((DM[masterFace_[s]] - D[fc[i]]) & n) + offset_[s])*n;
        }

        // The master receives the face's force by the overlap weights,
        // as one pressure per slave face
        forAll(faces[i], k)
        {
            FM[faces[i][k]] -= weights[i][k]*F;
        }
        slaveForce[i] = F;
        slavePressure[i] = (F & n)/slave.magSf()[i];
    }

    masterForce = pair_.masterSlice(pair_.sumOverProcessors(FM, tag_)());
}
