/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactInterfaceCoupling.H"
#include "processorSum.H"

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
    return max
    (
        n1*cmptMag(n),
        vector::uniform(minImplicitWeight_)
    );
}


Foam::vector Foam::contactInterfaceCoupling::faceWeights(const label i) const
{
    return tied_[i] ? vector::one : implicitWeights(normal_[i]);
}


Foam::vector Foam::contactInterfaceCoupling::lawPart
(
    const label i,
    const vector& v
) const
{
    return tied_[i] ? v : vector(normal_[i]*(normal_[i] & v));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactInterfaceCoupling::contactInterfaceCoupling
(
    const contactPatchPair& pair
)
:
    pair_(pair),
    start_(1, 0),
    nMaster_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactInterfaceCoupling::set(const inputs& in)
{
    const fvPatch& slave = pair_.slavePatch();
    const scalarField& magS = slave.magSf();
    const labelListList& faces = pair_.overlapFaces();
    const List<scalarList>& weights = pair_.overlapWeights();

    nMaster_ = pair_.nMasterFaces();
    normal_ = in.normal;
    explicitForce_.setSize(slave.size());
    tied_.setSize(slave.size());
    forAll(tied_, i)
    {
        tied_[i] = in.coupled[i] && in.tied.size() && in.tied[i];
    }

    DynamicList<label> start(slave.size() + 1);
    DynamicList<label> mf;
    DynamicList<scalar> coeff;
    DynamicList<vector> offset;
    DynamicList<scalar> area;
    start.append(0);

    forAll(faces, i)
    {
        const vector& n = in.normal[i];
        explicitForce_[i] =
            in.tangentialTraction.size()
          ? vector(in.tangentialTraction[i]*magS[i])
          : vector::zero;

        if (!in.coupled[i])
        {
            explicitForce_[i] += in.pressure0[i]*n*magS[i];
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
                if (tied_[i])
                {
                    // The vector gap G = gRef n - (I - n n) R_i + (D_fi -
                    // sum_j w_ij D_fj) is zero in stick: held to the stick
                    // point R_i of the step's start tangentially, closed
                    // normally; the explicit tractions enter whole
                    const vector& R = in.stickPoint[i];
                    offset.append
                    (
                       -gRef*n
                      + (R - n*(n & R))
                      + rs*in.slaveC[i]
                      - rm*in.masterC[j]
                      + in.compliance[i]
                       *(
                            in.pressure0[i]*n
                          + (
                                in.tangentialMultiplier.size()
                              ? in.tangentialMultiplier[i]
                              : vector::zero
                            )
                        )
                    );
                }
                else
                {
                    offset.append
                    (
                        n
                       *(
                           -gRef
                          + rs*(in.slaveC[i] & n)
                          - rm*(in.masterC[j] & n)
                          + in.compliance[i]*in.pressure0[i]
                        )
                    );
                }
            }
        }
        start.append(mf.size());
    }

    start_.transfer(start);
    masterFace_.transfer(mf);
    coeff_.transfer(coeff);
    offset_.transfer(offset);
    area_.transfer(area);

    if (in.D)
    {
        correctDeferred(*in.D, in.masterDelta/in.masterK, in.masterMagSf);
    }
}


void Foam::contactInterfaceCoupling::correctDeferred
(
    const vectorField& D,
    const scalarField& masterR,
    const scalarField& masterMagSf
)
{
    // Delta = r_j (t_j(Delta).n + p_ij(Delta)) is an affine map of Delta
    // with a contraction factor r_j k_ij < 1 (k_ij holds r_j in series),
    // solved to its fixed point at this D, so that the law is a function of
    // D alone, not of the law of an earlier corrector. For a soft master
    // against a stiff slave the factor is (delta_j/K_j)/(delta_i/K_i +
    // delta_j/K_j), 0.999 at 1000:1, and plain sweeps stop far from the
    // fixed point; Anderson's secant step on the sweeps is GMRES on the
    // affine map (Walker & Ni 2011) and needs about as many sweeps as the
    // map has distinct clusters of eigenvalues.
    const vectorField DM(masterCellValues(D));
    const List<vector> base(offset_);
    const label nSub = offset_.size();
    std::vector<double> x(3*nSub, 0.0), g(3*nSub), xNext;
    List<vector> p;
    vectorField F;

    scalar baseScale = 0;
    for (const vector& b : base)
    {
        baseScale = max(baseScale, cmptMax(cmptMag(b)));
    }
    reduce(baseScale, maxOp<scalar>());

    c4f::coupling::AndersonParameters params;
    params.depth = maxDeferredDepth_;
    c4f::coupling::AndersonAcceleration anderson
    (
        params,
        processorSumReduction()
    );

    nDeferredIter_ = 0;
    for (label iter = 0; iter < maxDeferredIter_; ++iter)
    {
        forAll(offset_, s)
        {
            offset_[s] = base[s] + vector(x[3*s], x[3*s + 1], x[3*s + 2]);
        }
        slaveForces(D, DM, F, &p);
        const vectorField TM
        (
            pair_.sumOverProcessors(masterTransfer(F)(), tag_)/masterMagSf
        );

        scalar change = 0;
        forAll(normal_, i)
        {
            for (label s = start_[i]; s < start_[i+1]; ++s)
            {
                // Delta_ij = r_j (t_j + t_ij), the part the law acts on
                const vector d
                (
                    lawPart
                    (
                        i,
                        masterR[masterFace_[s]]*(TM[masterFace_[s]] + p[s])
                    )
                );
                for (direction c = 0; c < 3; ++c)
                {
                    g[3*s + c] = d[c];
                    change = max(change, mag(g[3*s + c] - x[3*s + c]));
                }
            }
        }
        ++nDeferredIter_;

        // Round-off of the correction itself bounds what can be reached
        scalar scale = baseScale;
        for (const double v : g)
        {
            scale = max(scale, mag(v));
        }
        if
        (
            returnReduce(change, maxOp<scalar>())
         <= 1e-12*returnReduce(scale, maxOp<scalar>())
        )
        {
            // offset_ holds base + x, whose map value g is within the
            // tolerance of x
            break;
        }

        anderson.update(x, g, xNext);
        x.swap(xNext);
    }
}


void Foam::contactInterfaceCoupling::slaveForces
(
    const vectorField& D,
    const vectorField& DM,
    vectorField& F,
    List<vector>* subTraction
) const
{
    const labelUList& fc = pair_.slavePatch().faceCells();

    F.setSize(normal_.size());
    if (subTraction)
    {
        subTraction->setSize(coeff_.size());
    }

    forAll(normal_, i)
    {
        F[i] = explicitForce_[i];
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            const vector ts
            (
                coeff_[s]/area_[s]
               *lawPart(i, DM[masterFace_[s]] - D[fc[i]] + offset_[s])
            );
            F[i] += area_[s]*ts;
            if (subTraction)
            {
                (*subTraction)[s] = ts;
            }
        }
    }
}


Foam::tmp<Foam::vectorField> Foam::contactInterfaceCoupling::masterTransfer
(
    const vectorField& slaveForce
) const
{
    // The master receives each slave face's force by the overlap weights,
    // as one pressure per slave face
    const labelListList& faces = pair_.overlapFaces();
    const List<scalarList>& weights = pair_.overlapWeights();

    tmp<vectorField> tFM(new vectorField(nMaster_, Zero));
    vectorField& FM = tFM.ref();
    forAll(faces, i)
    {
        forAll(faces[i], k)
        {
            FM[faces[i][k]] -= weights[i][k]*slaveForce[i];
        }
    }
    return tFM;
}


Foam::tmp<Foam::vectorField> Foam::contactInterfaceCoupling::slaveDiag() const
{
    tmp<vectorField> td(new vectorField(normal_.size(), Zero));
    vectorField& d = td.ref();
    forAll(d, i)
    {
        const vector w(faceWeights(i));
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
        const vector w(faceWeights(i));
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
        const scalar w = faceWeights(i)[cmpt];
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
        const scalar w = faceWeights(i)[cmpt];
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
    slaveForces(D, masterCellValues(D), slaveForce);

    slavePressure = (slaveForce & normal_)/pair_.slavePatch().magSf();

    masterForce =
        pair_.masterSlice
        (
            pair_.sumOverProcessors(masterTransfer(slaveForce)(), tag_)()
        );
}
