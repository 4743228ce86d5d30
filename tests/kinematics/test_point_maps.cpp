// kinematics/point_maps: the polar decomposition, and the Hencky strain and its inverse,
// against maps built by hand and the eigen-decomposition (Eigen's).
#include <catch2/catch.hpp>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "kinematics/point_maps.hpp"

using namespace dda;

TEST_CASE("polar decomposition rebuilds the map from its angle and Biot strain",
          "[kinematics][polar]") {
  // A block turned 3 rad and strained 30 % (shear included): F = R(r) (I + E^).
  const Vec3 strain(0.3, -0.12, 0.25);
  const Mat2 f = rotation_matrix(3.0) * (Mat2::Identity() + strain_tensor(strain));
  const PolarDecomposition p = polar_decomposition(f, 3.0 + 0.1);
  // A few roundings of O(1) entries.
  CHECK(std::abs(p.angle - 3.0) < 4e-15);
  CHECK((p.strain - strain).norm() < 4e-15);
  // The branch follows `near`: the same map seen from 2 pi further on.
  CHECK(std::abs(polar_decomposition(f, 3.0 + 2.0 * M_PI).angle - (3.0 + 2.0 * M_PI)) < 1e-14);
}

TEST_CASE("the Hencky strain is ln U, and stretch_from_hencky its inverse",
          "[kinematics][polar]") {
  // Against ln of the eigenvalues on the eigenvectors (Eigen's symmetric solver), from
  // round-off strains (where the closed form's series act) to 40 %.
  for (const Vec3& biot : {Vec3(1e-9, -2e-9, 3e-9), Vec3(1e-5, 1e-5, 0.0), Vec3(2e-3, -1e-3, 4e-3),
                           Vec3(0.05, -0.02, 0.03), Vec3(0.4, -0.1, -0.3), Vec3(0.2, 0.2, 0.0)}) {
    const Mat2 u = Mat2::Identity() + strain_tensor(biot);
    const Eigen::SelfAdjointEigenSolver<Mat2> eig(u);
    const Mat2 log_u = eig.eigenvectors() * eig.eigenvalues().array().log().matrix().asDiagonal() *
                       eig.eigenvectors().transpose();
    const Vec3 expected(log_u(0, 0), log_u(1, 1), 2.0 * log_u(0, 1));
    const Vec3 h = hencky_from_stretch(biot);
    INFO("biot " << biot.transpose() << ": " << h.transpose() << " vs " << expected.transpose());
    // The eigen route takes the log of eigenvalues near 1, which keeps only their absolute
    // round-off (a few ulps of 1, 2e-16 each); the closed form keeps the digits (log1p).
    // So the bound is the reference's: 1e-15 absolute plus 1e-14 relative.
    CHECK((h - expected).norm() <= 1e-15 + 1e-14 * biot.norm());
    // And back: exp(ln U) = U, to round-off relative to the strain (expm1 keeps the digits).
    CHECK((stretch_from_hencky(h) - biot).norm() <= 1e-15 * biot.norm());
    // For small strains the two measures agree to first order: |ln U - E| <= |E|^2.
    if (biot.norm() < 1e-2) CHECK((h - biot).norm() <= biot.squaredNorm());
  }
}

TEST_CASE("hencky_frame_map turns the stretch exp(H)", "[kinematics][polar]") {
  const Vec3 biot(0.05, -0.02, 0.03);
  const Mat2 expected = rotation_matrix(0.7) * (Mat2::Identity() + strain_tensor(biot));
  CHECK((hencky_frame_map(0.7, hencky_from_stretch(biot)) - expected).norm() < 1e-15);
}
