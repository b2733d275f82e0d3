"""Print setup of a report sheet: A4, orientation, fit to the page width, page header and
footer.

What this module guarantees: every sheet prints on A4 in the orientation its width asks for
(:func:`orientation_for`), fitted to the page width (never a column cut from its row labels),
with its header rows repeated on every page, a page header naming the report, the sheet and
the input file, and a footer with the run date, the version and ``page x of y``; a text from
an input is never read as a header or footer control code (:func:`header_footer_text`,
:func:`_escape`), and a header or footer stays within Excel's
:data:`EXCEL_MAX_HEADER_CHARS`.

References
----------
.. [1] Microsoft, "Excel specifications and limits": 255 characters in a page header or
   footer.
.. [2] ECMA-376 Part 1, 18.3.1.63 ``pageSetup`` (paperSize 9 = A4; ``fitToWidth`` and
   ``fitToHeight`` default to 1) and 18.3.1.46 ``headerFooter`` codes (``&P`` page, ``&N``
   pages, ``&&`` an ampersand, ``&8`` an 8-point font).
"""

from __future__ import annotations

import math
import re

#: Characters (UTF-16 code units) in a page header or footer, codes included [1]_.
EXCEL_MAX_HEADER_CHARS = 255
#: A4 paper, ECMA-376 ``paperSize`` code [2]_.
PAPER_A4 = 9
#: Page margins: left, right, top, bottom, header, footer. [in]
MARGINS = (0.5, 0.5, 0.75, 0.75, 0.3, 0.3)
#: Printable width and height of an A4 page inside :data:`MARGINS`, at 96 px per inch. [px]
PRINTABLE = {"portrait": (round((8.27 - 1.0) * 96), round((11.69 - 1.5) * 96)),
             "landscape": (round((11.69 - 1.0) * 96), round((8.27 - 1.5) * 96))}
#: Least scale, relative to the fit to the page width, a sheet is shrunk to so as to spare a
#: nearly empty page (:func:`height_fit`; sections sheets: ``write_sections_sheet``). [-]
MIN_EXTRA_SCALE = 0.85
#: A page less full than this, other than the last of its sheet, is a sparse page; a last
#: page less full than this is spared when a small shrink allows (:func:`height_fit`). [-]
SPARSE_LAST = 0.35
#: Least print scale of a sheet [-]: a table wider than the page at this scale prints in
#: blocks of columns, page after page, each repeating the table's key column (the row's id)
#: (:func:`column_pages`), never shrunk below it to fit the width.
MIN_PRINT_SCALE = 0.70
#: A literal ``&`` (doubled) before what XlsxWriter's ``set_header`` reads as an image code.
_IMAGE_CODE = re.compile(r"&&(?=G|\[Picture\])")


def _escape(text, limit=80):
    """Header/footer text: at most ``limit`` characters, made safe
    (:func:`header_footer_text`)."""
    text = str(text)
    if len(text) > limit:
        text = text[:limit - 3] + "..."
    return header_footer_text(text)


def orientation_for(pixels, height=0.0):
    """The orientation of a sheet ``pixels`` wide and ``height`` high [px].

    Portrait when the sheet fits the portrait width (8 % shrink allowed). Portrait also when
    a fit-to-width shrink to no less than :data:`MIN_PRINT_SCALE` puts it on a portrait page
    and that prints it on fewer pages than landscape (:func:`pages_for`, with a 10 % margin on
    the estimated height), or when it is long (more than a landscape page); else landscape.
    """
    width, _ = PRINTABLE["portrait"]
    land_width, land_height = PRINTABLE["landscape"]
    if pixels <= 1.08 * width:
        return "portrait"
    if pixels <= width / MIN_PRINT_SCALE and (
            height * min(1.0, land_width / pixels) > 1.2 * land_height
            or pages_for("portrait", pixels, 1.1 * height)
            < pages_for("landscape", pixels, 1.1 * height)):
        return "portrait"
    return "landscape"


def column_pages(widths, orientation, keys=1):
    """The print scale and the column page breaks of a sheet whose columns are ``widths``
    px wide: fitted to the page width when that is at least :data:`MIN_PRINT_SCALE`; else in
    blocks of columns, each as wide as a page at that scale with the ``keys`` first columns
    (repeated on every page), printed at the largest scale (at most 1) that fits the widest
    block.

    Parameters
    ----------
    widths : sequence of float
        Width of each column, in order. [px]
    orientation : str
    keys : int
        Columns printed at the left of every block.

    Returns
    -------
    scale : float
        [-]
    starts : list of int
        Index of the first column of each block after the first (none: one block).

    Examples
    --------
    Ten columns of 200 px on a landscape page (1026 px): 0.51 x to fit, so two blocks, the
    key and five columns (1200 px) then the key and four, printed at 0.855 x.

    >>> scale, starts = column_pages([200] * 10, "landscape")
    >>> round(scale, 3), starts
    (0.855, [6])
    """
    width = PRINTABLE[orientation][0]
    widths = [float(w) for w in widths]
    fit = min(1.0, width / max(sum(widths), 1.0))
    keys = min(int(keys), len(widths))
    if fit >= MIN_PRINT_SCALE or len(widths) <= keys + 1:
        return fit, []
    key = sum(widths[:keys])

    def blocks(room):
        starts, used, widest = [], key, key
        for j in range(keys, len(widths)):
            if used > key and used + widths[j] > room:
                starts.append(j)
                used = key
            used += widths[j]
            widest = max(widest, used)
        return starts, widest

    # as few blocks as at the least scale, made as even as they can be (the narrowest room
    # that gives no more blocks: bisection on the room)
    starts, widest = blocks(width / MIN_PRINT_SCALE)
    low, high = key + max(widths[keys:]), width / MIN_PRINT_SCALE
    for _ in range(40):
        mid = 0.5 * (low + high)
        if len(blocks(mid)[0]) <= len(starts):
            high = mid
        else:
            low = mid
    starts, widest = blocks(high)
    return min(1.0, width / widest), starts


def page_pixels(orientation, pixels):
    """Printable height of a page in sheet pixels, after the fit-to-width shrink of a sheet
    ``pixels`` wide. [px]"""
    width, height = PRINTABLE[orientation]
    return height / min(1.0, width / max(pixels, 1.0))


def pages_for(orientation, pixels, height):
    """Pages that ``height`` pixels of rows take, fitted to the page width (at least 1)."""
    return max(1, math.ceil(height / page_pixels(orientation, pixels) - 1e-9))


def height_fit(orientation, pixels, height):
    """The page count a sheet of flowing rows (no manual page break) is fitted to, or 0 (no
    limit on its height).

    A sheet whose estimated last page would be under :data:`SPARSE_LAST` full is fitted to
    one page fewer when that shrinks it by at most ``1 -`` :data:`MIN_EXTRA_SCALE` more than
    the fit to width, and not below :data:`MIN_PRINT_SCALE` (the estimate taken 3 % high): a
    nearly empty last page is spared at a small loss of size. Excel and LibreOffice then
    choose the scale that meets both the
    width and the page count.

    Parameters
    ----------
    orientation : str
    pixels : float
        Width of the sheet's used columns. [px]
    height : float
        Estimated height of its rows. [px]

    Returns
    -------
    int
    """
    pages = 1.03 * height / page_pixels(orientation, pixels)
    whole = math.ceil(pages - 1e-9)
    fit = min(1.0, PRINTABLE[orientation][0] / max(pixels, 1.0))
    if whole >= 2 and pages - (whole - 1) < SPARSE_LAST and (whole - 1) / pages >= \
            MIN_EXTRA_SCALE and fit * (whole - 1) / pages >= MIN_PRINT_SCALE:
        return whole - 1
    return 0


def print_setup(ws, *, pixels, height=0.0, title_rows=None, sheet_title="", info=None,
                pages=0, scale=None, orientation=None, column_breaks=(), key_columns=0):
    """Page setup of one sheet: A4, orientation from its width, fitted to the page width
    (and to ``pages`` pages high, or at a fixed ``scale``), header rows repeated, page header
    and footer.

    Parameters
    ----------
    ws : xlsxwriter.worksheet.Worksheet
    pixels : float
        Width of the sheet's used columns. [px]
    height : float
        Estimated height of its rows (long sheets print portrait when they can). [px]
    title_rows : int, optional
        Rows 1..title_rows are printed at the top of every page.
    sheet_title : str
        Centre of the page header.
    info : ReportInfo, optional
        Report title and input file (page header), run date, version and document number
        (footer).
    pages : int
        Pages high the sheet is fitted to (0: as many as it needs, :func:`height_fit`).
    scale : int, optional
        A fixed print scale [%] instead of the fit (a sheet with manual page breaks, which a
        fit to a page count would drop): at most the fit to the page width.
    orientation : str, optional
        The orientation, when the caller has chosen it (:func:`orientation_for`).
    column_breaks : sequence of int
        Columns that start a new printed block (:func:`column_pages`); then ``scale`` is
        the block's scale, not capped at the fit to the whole width.
    key_columns : int
        Columns printed at the left of every block.

    Returns
    -------
    str
        The orientation chosen.
    """
    orientation = orientation or orientation_for(pixels, height)
    ws.set_paper(PAPER_A4)
    orient(ws, orientation)
    if column_breaks:  # blocks of columns, down then over, the key columns on each
        ws.set_print_scale(max(10, min(100, math.floor(scale))))
        ws.set_v_pagebreaks(sorted(int(j) for j in column_breaks))
        if key_columns:
            ws.repeat_columns(0, int(key_columns) - 1)
    elif scale is not None:
        width = PRINTABLE[orientation][0]
        ws.set_print_scale(max(10, min(int(scale), math.floor(100 * min(1.0, width / pixels)))))
    else:
        ws.fit_to_pages(1, int(pages))  # 1 page wide, ``pages`` high (0: as many as needed)
    left, right, top, bottom, header, footer = MARGINS
    ws.set_margins(left=left, right=right, top=top, bottom=bottom)
    if title_rows:
        ws.repeat_rows(0, int(title_rows) - 1)
    title = info.title if info is not None else "slingloads report"
    narrow = orientation == "portrait"
    right = " | ".join(t for t in ((info.document, info.input_name) if info is not None
                                   else ()) if t)
    ws.set_header(_header_footer([(title, 45 if narrow else 60),
                                  (sheet_title or ws.name, 45 if narrow else 70),
                                  (right, 45)]), {"margin": header})
    ws.set_footer(_header_footer([(f"run {info.run_date}" if info is not None else "", 40),
                                  None, (info.software if info is not None else "slingloads",
                                         45)]), {"margin": footer})
    return orientation


def orient(ws, orientation):
    """Print ``ws`` in ``orientation`` (``"portrait"`` or ``"landscape"``)."""
    if orientation == "portrait":
        ws.set_portrait()
    else:
        ws.set_landscape()


def _header_footer(parts):
    """A page header or footer: left, centre and right parts in 8 pt, ``&L&8 left&C&8
    centre&R&8 right`` [2]_.

    Parameters
    ----------
    parts : sequence of 3 (str, int) or None
        ``(text, most characters)`` of each part, the text made safe by :func:`_escape`;
        None for the page number, ``page &P of &N``.

    Returns
    -------
    str
        At most :data:`EXCEL_MAX_HEADER_CHARS` UTF-16 units: the longest part is shortened
        while it is longer (only a text full of ``&``, each written ``&&``, comes near).
    """
    limits = [None if p is None else p[1] for p in parts]
    while True:
        texts = ["page &P of &N" if p is None else _escape(p[0], limit)
                 for p, limit in zip(parts, limits, strict=True)]
        text = "".join(f"&{key}&8 {part}" for key, part in zip("LCR", texts, strict=True))
        # XlsxWriter reads &G and &[Picture] as image codes, even after a literal &&: an
        # 8 pt size code between (the part's size already) keeps them text
        text = _IMAGE_CODE.sub("&&&8", text)
        shorter = [k for k, limit in enumerate(limits) if limit is not None and limit > 10]
        if _utf16_units(text) <= EXCEL_MAX_HEADER_CHARS or not shorter:
            return text
        k = max(shorter, key=lambda k: _utf16_units(texts[k]))
        limits[k] = max(10, min(limits[k], len(str(parts[k][0]))) - 5)


def _utf16_units(text):
    """Length of ``text`` as Excel counts it: UTF-16 code units."""
    return len(text.encode("utf-16-le")) // 2


def header_footer_text(text):
    """Text from an input made safe for a printed header or footer: there ``&`` starts a
    control code (``&P`` page number, ``&"font"``, ``&[Path]``...), so it is doubled, and
    control characters are dropped.

    >>> header_footer_text("R&D study &P")
    'R&&D study &&P'
    """
    text = "".join(c for c in str(text) if c >= " " or c == "\n")
    return text.replace("&", "&&")
