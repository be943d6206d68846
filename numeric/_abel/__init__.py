"""The private engine of :mod:`hertzmdr.numeric.abel` (the public face):

- ``interpolation``: the piecewise Lagrange interpolant in s = x^2 (stencils, coefficients);
- ``moments``: the integrals of its local variable against the (5.59)/(5.61) kernels;
- ``operators``: the transforms as matrices on the samples, built, cached and applied;
- ``edge``: the end of the support (the contact radius) found from the samples.
"""
