"""Input/output layer: workbooks in, Excel/CSV reports and plots out, units at the boundary.

The physical models and analyses never import this package.
"""
