"""The plots sheet of a report workbook: PNG images one under another, print-ready.

What this module guarantees: every image is scaled to the printable width, at most half a
page high (two to a page) unless it is a tall figure, never cut by a page break, under its
title wrapped to the page; its size and resolution are read from the PNG itself, and anything
but a PNG image is refused.
"""

from __future__ import annotations

import io
import math
import textwrap

from slingloads.errors import InputError
from slingloads.io.common.excel_cells import (
    CHAR_PIXELS,
    ROW_PIXELS,
    TITLE_STYLE,
    SheetWriter,
    check_sheet_name,
    column_pixels,
)
from slingloads.io.common.excel_print import PRINTABLE, orient, print_setup
from slingloads.io.common.excel_tables import TableColumns, set_widths
from slingloads.io.common.figures import collect_pngs, figure_png


def _image_box(width, height, page_rows, page_width):
    """Displayed size of an image [px] and the rows it takes: the printable width, at most
    half a page high (two plots to a page), or a whole page for a tall figure."""
    half = (page_rows // 2 - 3) * ROW_PIXELS
    full = (page_rows - 3) * ROW_PIXELS
    scale = page_width / width
    limit = half if height * scale <= 1.3 * half else full
    scale = min(scale, limit / height)
    w, h = int(width * scale), int(height * scale)
    return w, h, math.ceil(h / ROW_PIXELS) + 2


def _png_geometry(png):
    """Size and resolution of a PNG image, from its ``IHDR`` and ``pHYs`` chunks.

    Parameters
    ----------
    png : bytes

    Returns
    -------
    (int, int, float, float)
        Width and height [px], horizontal and vertical resolution [dots per inch] as
        XlsxWriter reads them (96 when the file states none, or none in metres).

    Raises
    ------
    InputError
        If ``png`` is not a PNG image.
    """
    if png[:8] != b"\x89PNG\r\n\x1a\n" or png[12:16] != b"IHDR":
        raise InputError("a report image must be a PNG image", bytes(png[:8]))
    width, height = int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
    dpi = (96.0, 96.0)
    at = 8
    while at + 8 <= len(png):
        size, kind = int.from_bytes(png[at:at + 4], "big"), png[at + 4:at + 8]
        if kind == b"pHYs" and size >= 9:
            x, y = int.from_bytes(png[at + 8:at + 12], "big"), \
                int.from_bytes(png[at + 12:at + 16], "big")
            if png[at + 16] == 1 and x > 0 and y > 0:  # pixels per metre
                dpi = (x * 0.0254, y * 0.0254)
            break
        if kind in (b"IDAT", b"IEND"):  # pHYs comes before the image data
            break
        at += 12 + size
    return width, height, *dpi


def _insert_png(ws, row, png, width, height, name):
    """Embed ``png`` with its top left corner at the top left of cell (row, A), displayed
    ``width`` x ``height`` px (as at 96 dpi), moving with its cell (not sized with it)."""
    w, h, x_dpi, y_dpi = _png_geometry(png)
    # XlsxWriter displays w * x_scale * 96 / x_dpi pixels
    ws.insert_image(row, 0, name, {
        "image_data": io.BytesIO(png), "object_position": 2,
        "x_scale": width * x_dpi / (96.0 * w), "y_scale": height * y_dpi / (96.0 * h)})


def write_images_sheet(wb, name, images, *, info=None, orientation="portrait", title=""):
    """Embed PNG images one under another, each under its title, scaled to the printable
    width, with a page break wherever the next one would not fit on the page.

    Parameters
    ----------
    wb : ReportWorkbook
        The workbook being written.
    name : str
        Sheet name.
    images : mapping of str to (matplotlib.figure.Figure or bytes)
        Title -> figure or PNG bytes.
    info : ReportInfo, optional
        Page header and footer.
    orientation : str
        ``"portrait"`` or ``"landscape"``.
    title : str
        Printed in the page header (default: ``Plots (n)``).

    Returns
    -------
    list of str
        ``[name]``.
    """
    ws = wb.add_worksheet(check_sheet_name(name))
    page_width, page_height = PRINTABLE[orientation]
    page_rows = page_height // ROW_PIXELS
    width = (page_width - 10 - 5) // 7
    set_widths(ws, TableColumns({0: width}, set()))
    pixels = column_pixels(width)
    print_setup(ws, pixels=pixels if orientation == "portrait" else 2 * pixels,
                sheet_title=title or f"Plots ({len(images)})", info=info)
    orient(ws, orientation)
    writer = SheetWriter(wb, ws)
    used = 0
    pngs = collect_pngs(images.values())  # drawn here when the helper is behind
    for k, (title, figure) in enumerate(zip(images, pngs, strict=True)):
        png = figure_png(figure)
        size = _png_geometry(png)[:2]
        w, h, rows = _image_box(*size, page_rows, pixels - 10)
        # a title wider than the page is cut when printed: wrapped (12 pt bold ~ 1.45 x)
        lines = textwrap.wrap(str(title), max(20, int((pixels - 10) / (CHAR_PIXELS * 1.45))))
        lines = lines or [""]
        rows += len(lines) - 1
        if used and used + rows > page_rows:
            writer.page_break()
            used = 0
        for line in lines[:-1]:
            writer.append([line], TITLE_STYLE)
        writer.append([lines[-1]], TITLE_STYLE)
        _insert_png(ws, writer.row, png, w, h, f"plot{k + 1}.png")
        writer.blank(rows - 1)
        used += rows
    writer.close()
    return [name]
