"""Machinery shared by every analysis's input and output, one concern per module.

Reading a workbook:

* :mod:`~slingloads.io.common.xlsx_source`: the file and its ZIP container checked (zip and
  XML bombs), the sheets streamed row by row, the cells parsed;
* :mod:`~slingloads.io.common.values`: cell values to numbers, flags and texts, checked
  against their limits; :mod:`~slingloads.io.common.units`: units to SI;
* :mod:`~slingloads.io.common.workbook`: the typed sheet reader (tables with units in their
  headers, every value checked, every problem located), giving
  :class:`~slingloads.io.common.table.Table` objects;
  :mod:`~slingloads.io.common.parameters`: the Study sheet;
  :mod:`~slingloads.io.common.referenced`: the CSV files a workbook names;
  :mod:`~slingloads.io.common.schema`: the sheets' and parameters' declarations;
* :mod:`~slingloads.io.common.locate`: the one way an error a model raises is put at the
  cell its value came from.

Writing a report: :mod:`~slingloads.io.common.excel` (the workbook writer, with its parts
``excel_cells``, ``excel_print``, ``excel_tables``, ``excel_sections`` and
``excel_images``),
:mod:`~slingloads.io.common.report`, :mod:`~slingloads.io.common.cover`,
:mod:`~slingloads.io.common.formats`, :mod:`~slingloads.io.common.csvout`,
:mod:`~slingloads.io.common.figures`; publishing the files:
:mod:`~slingloads.io.common.atomic` and :mod:`~slingloads.io.common.ownership`.

Nothing here knows any particular analysis (no module imports ``slingloads.io.loads``,
``slingloads.io.lateral`` or ``slingloads.io.chute``).
"""
