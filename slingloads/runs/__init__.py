"""Running a study: the analyses a study asks for, in order, with their hand-offs.

Between the analyses (:mod:`slingloads.analyses`, physics only) and the input/output layer
(:mod:`slingloads.io`, workbooks in and reports out): it reads no file and writes no report.
"""
