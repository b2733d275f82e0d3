"""Machinery shared by every analysis's input and output: workbook reading, schema types,
units, Excel writing, atomic publication of the files.

Nothing here knows any particular analysis (no module imports ``slingloads.io.loads``,
``slingloads.io.lateral`` or ``slingloads.io.chute``).
"""
