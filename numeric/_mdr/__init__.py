"""The private engine of :mod:`hertzmdr.numeric.mdr` (the public face: Profile, Solution):

- ``spline``: the piecewise spline representation of f at one resolution (``Rep``);
- ``kinks``: where f' jumps, and the exact branch-point terms of g, g' and p there;
- ``quadrature``: (5.52) g, g' and the (5.57) integral of g by quadrature of the spline;
- ``tables``: the smooth remainders of g and g' tabulated in x or sqrt(x - b) (``Seg``);
- ``operators``: the pressure (5.59) and the displacement (5.60) from the tables;
- ``resolution``: the pairs of representations (coarse, fine) and how each kind of profile
  refines them (samples: quadrature; callables: grid);
- ``solve``: (5.55) and (5.57) at a depth or force, and the bound of their error.
"""
