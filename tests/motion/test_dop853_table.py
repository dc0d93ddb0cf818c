"""The DOP853 table written out in slidespin.motion._dop853 is scipy's, bit for bit, and is a
Runge–Kutta method of order 8 (independent checks: the row sums and the order conditions)."""

import numpy as np
from scipy.integrate._ivp import dop853_coefficients as scipy_table

from slidespin.motion import _dop853 as table


def test_table_is_scipys_bit_for_bit():
    ns = scipy_table.N_STAGES
    assert table.N_STAGES == ns
    assert np.array_equal(table.A, scipy_table.A[:ns, :ns])
    assert np.array_equal(table.B, scipy_table.B)
    assert np.array_equal(table.C, scipy_table.C[:ns])
    assert np.array_equal(table.E3, scipy_table.E3)
    assert np.array_equal(table.E5, scipy_table.E5)


def test_table_is_a_consistent_method_of_high_order():
    A, b, c = table.A, table.B, table.C
    assert np.allclose(A.sum(axis=1), c, atol=1e-14)  # c_i = Σ_j a_ij
    assert np.allclose(np.triu(A), 0.0)  # explicit
    # quadrature order conditions Σ b_i c_i^(k-1) = 1/k for k = 1..8
    for k in range(1, 9):
        assert abs(b @ c ** (k - 1) - 1.0 / k) < 1e-13, k
    # the error estimates vanish on the quadrature of a constant (they weight differences)
    assert abs(table.E5.sum()) < 1e-13 and abs(table.E3.sum()) < 1e-13


def test_dense_output_table_is_scipys_bit_for_bit():
    assert np.array_equal(table.A_EXTRA, scipy_table.A[scipy_table.N_STAGES + 1 :])
    assert np.array_equal(table.C_EXTRA, scipy_table.C[scipy_table.N_STAGES + 1 :])
    assert np.array_equal(table.D, scipy_table.D)
