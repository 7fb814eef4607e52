// Unit tests of the master-to-slave transfer, src/kernels/transfer/
// consistentTransfer, with the overlap weights of polygonOverlap on
// non-matching tilings: a uniform master field comes back exactly (2D
// strips 7 on 10 faces, 3D 7 x 5 on 10 x 8, tilted); a linear one within
// |grad f| h_master/2 and first order under refinement of the master
// (exact on matching faces); the transfer is the adjoint of the
// conservative force transfer (the work of the slave forces on the
// transferred field is the master forces' work); faces without overlap
// and malformed input.

#include "consistentTransfer.H"
#include "polygonOverlap.H"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

using namespace c4f::transfer;
using V = Eigen::Vector3d;

namespace
{

//- Overlaps of a slave tiling on a master tiling, as contactPatchPair
//  keeps them: per slave face the master faces it overlaps and their
//  conservative weights
struct Overlaps
{
    std::vector<std::vector<int>> faces;
    std::vector<std::vector<double>> weights;
};

Overlaps overlaps(const std::vector<Polygon>& slave, const std::vector<Polygon>& master)
{
    Overlaps o;
    for (const Polygon& s : slave)
    {
        std::vector<double> a;
        for (const Polygon& m : master)
        {
            a.push_back(overlapArea(s, m));
        }
        const std::vector<double> w(conservativeWeights(a));
        std::vector<int> f;
        std::vector<double> ww;
        for (std::size_t j = 0; j < w.size(); ++j)
        {
            if (w[j] > 0)
            {
                f.push_back(int(j));
                ww.push_back(w[j]);
            }
        }
        o.faces.push_back(f);
        o.weights.push_back(ww);
    }
    return o;
}

//- nx x ny rectangles tiling [0,1] x [0,Ly] at height z, facing +z (up)
//  or -z, moved by R x + t
std::vector<Polygon> tiling
(
    int nx, int ny, double Ly, double z, bool up,
    const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity(),
    const V& t = V::Zero()
)
{
    std::vector<Polygon> faces;
    for (int j = 0; j < ny; ++j)
    {
        for (int i = 0; i < nx; ++i)
        {
            const double x0 = double(i)/nx, x1 = double(i + 1)/nx;
            const double y0 = Ly*j/ny, y1 = Ly*(j + 1)/ny;
            Polygon p{V(x0, y0, z), V(x1, y0, z), V(x1, y1, z), V(x0, y1, z)};
            if (!up)
            {
                std::reverse(p.begin(), p.end());
            }
            for (V& x : p)
            {
                x = R*x + t;
            }
            faces.push_back(p);
        }
    }
    return faces;
}

V centre(const Polygon& p)
{
    V c(V::Zero());
    for (const V& x : p)
    {
        c += x;
    }
    return c/double(p.size());
}

std::vector<double> sampled(const std::vector<Polygon>& faces, const V& grad, double f0)
{
    std::vector<double> f;
    for (const Polygon& p : faces)
    {
        f.push_back(f0 + grad.dot(centre(p)));
    }
    return f;
}

Eigen::Matrix3d tilt()
{
    return
        (
            Eigen::AngleAxisd(0.5, V(1, 2, 3).normalized())
        ).toRotationMatrix();
}

} // End anonymous namespace


TEST(ConsistentTransfer, uniformFieldComesBackExactly)
{
    // 2D strips (one cell thick, 7 slave faces on 10 master faces, as the
    // contact patch test), a 3D tiling 7 x 5 on 10 x 8, and the same
    // turned about (1, 2, 3)
    const Eigen::Matrix3d I(Eigen::Matrix3d::Identity());
    const V t(0.3, -0.2, 1.5);
    for (const auto& c :
         {
             std::make_tuple(7, 1, 10, 1, I),
             std::make_tuple(7, 5, 10, 8, I),
             std::make_tuple(7, 5, 10, 8, tilt())
         })
    {
        const Eigen::Matrix3d R(std::get<4>(c));
        const std::vector<Polygon> master =
            tiling(std::get<2>(c), std::get<3>(c), 0.8, 0, true, R, t);
        const std::vector<Polygon> slave =
            tiling(std::get<0>(c), std::get<1>(c), 0.8, 1e-3, false, R, t);
        const Overlaps o(overlaps(slave, master));
        for (const double u : {-3.7e9, 1.0, 2.5e-7})
        {
            const std::vector<double> f =
                consistentTransfer(o.faces, o.weights, std::vector<double>(master.size(), u));
            ASSERT_EQ(f.size(), slave.size());
            for (std::size_t i = 0; i < f.size(); ++i)
            {
                EXPECT_NEAR(f[i], u, 4e-16*std::abs(u)) << i;
            }
        }
    }
}

TEST(ConsistentTransfer, linearFieldToTheMastersOrder)
{
    // f = f0 + b x sampled at the master face centres: the slave value is
    // the overlap-weighted mean of piecewise-constant values, within
    // |b| h_m/2 of f at the slave centre, first order in h_m; exact where
    // each slave face is a union of master faces
    const double b = 2.0, f0 = 1.0;
    double previous = 0;
    for (const int n : {10, 20, 40, 80, 160})
    {
        const std::vector<Polygon> master = tiling(n, 1, 0.1, 0, true);
        const std::vector<Polygon> slave = tiling(7, 1, 0.1, 1e-3, false);
        const Overlaps o(overlaps(slave, master));
        const std::vector<double> f =
            consistentTransfer(o.faces, o.weights, sampled(master, V(b, 0, 0), f0));
        double err = 0;
        for (std::size_t i = 0; i < f.size(); ++i)
        {
            err = std::max(err, std::abs(f[i] - (f0 + b*centre(slave[i]).x())));
        }
        const double hm = 1.0/n;
        EXPECT_LE(err, 0.5*b*hm + 1e-14) << n;
        if (previous > 0)
        {
            // First order: halving h_m at least halves the bound; the
            // error itself falls by 1.5 to 2.5 (it depends on where the
            // slave's edges fall in the master faces)
            EXPECT_LT(err, 0.7*previous) << n;
        }
        previous = err;
    }
    // Matching faces, and each slave face the union of two master faces
    for (const int n : {7, 14})
    {
        const std::vector<Polygon> master = tiling(n, 1, 0.1, 0, true);
        const std::vector<Polygon> slave = tiling(7, 1, 0.1, 1e-3, false);
        const Overlaps o(overlaps(slave, master));
        const std::vector<double> f =
            consistentTransfer(o.faces, o.weights, sampled(master, V(b, 0, 0), f0));
        for (std::size_t i = 0; i < f.size(); ++i)
        {
            EXPECT_NEAR(f[i], f0 + b*centre(slave[i]).x(), 1e-14) << n << " " << i;
        }
    }
    // 3D, linear in both directions, tilted: within |grad f| h_m/2
    const std::vector<Polygon> master = tiling(10, 8, 0.8, 0, true, tilt());
    const std::vector<Polygon> slave = tiling(7, 5, 0.8, 1e-3, false, tilt());
    const Overlaps o(overlaps(slave, master));
    const V grad(tilt()*V(1.0, -3.0, 0));
    const std::vector<double> f = consistentTransfer(o.faces, o.weights, sampled(master, grad, f0));
    for (std::size_t i = 0; i < f.size(); ++i)
    {
        EXPECT_LE(std::abs(f[i] - (f0 + grad.dot(centre(slave[i])))),
                  0.5*(1.0*0.1 + 3.0*0.1) + 1e-14) << i;
    }
}

TEST(ConsistentTransfer, adjointOfTheConservativeForceTransfer)
{
    // F_j = -sum_i w_ij F_i (contactPatchPair::masterForce); then
    // sum_i F_i f_i = -sum_j F_j f_j for any slave forces and master field
    const std::vector<Polygon> master = tiling(10, 8, 0.8, 0, true, tilt());
    const std::vector<Polygon> slave = tiling(7, 5, 0.8, 1e-3, false, tilt());
    const Overlaps o(overlaps(slave, master));
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 20; ++trial)
    {
        std::vector<double> Fs(slave.size()), fm(master.size());
        for (double& x : Fs) x = 1e6*u(gen);
        for (double& x : fm) x = 1e-3*u(gen);
        std::vector<double> Fm(master.size(), 0);
        for (std::size_t i = 0; i < slave.size(); ++i)
        {
            for (std::size_t k = 0; k < o.faces[i].size(); ++k)
            {
                Fm[o.faces[i][k]] -= o.weights[i][k]*Fs[i];
            }
        }
        const std::vector<double> fs = consistentTransfer(o.faces, o.weights, fm);
        double ws = 0, wm = 0, scale = 0;
        for (std::size_t i = 0; i < slave.size(); ++i)
        {
            ws += Fs[i]*fs[i];
            scale += std::abs(Fs[i])*1e-3;
        }
        for (std::size_t j = 0; j < master.size(); ++j)
        {
            wm += Fm[j]*fm[j];
        }
        EXPECT_NEAR(ws, -wm, 1e-14*scale) << trial;
    }
}

TEST(ConsistentTransfer, facesWithoutOverlapAndMalformedInput)
{
    const std::vector<std::vector<int>> faces{{0, 1}, {}, {1}};
    const std::vector<std::vector<double>> weights{{0.25, 0.75}, {}, {1.0}};
    const std::vector<double> f = consistentTransfer(faces, weights, {4.0, 8.0}, -1.0);
    EXPECT_DOUBLE_EQ(f[0], 7.0);
    EXPECT_EQ(f[1], -1.0);
    EXPECT_EQ(f[2], 8.0);
    EXPECT_EQ(consistentTransfer(faces, weights, {4.0, 8.0})[1], 0.0);
    EXPECT_TRUE(consistentTransfer({}, {}, {1.0}).empty());

    EXPECT_THROW(consistentTransfer(faces, {{0.25, 0.75}}, {4.0, 8.0}), std::invalid_argument);
    EXPECT_THROW(consistentTransfer({{0, 1}}, {{1.0}}, {4.0, 8.0}), std::invalid_argument);
    EXPECT_THROW(consistentTransfer({{2}}, {{1.0}}, {4.0, 8.0}), std::invalid_argument);
    EXPECT_THROW(consistentTransfer({{-1}}, {{1.0}}, {4.0, 8.0}), std::invalid_argument);
}
