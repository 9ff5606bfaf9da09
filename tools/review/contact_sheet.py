"""The review set's contact sheet: the views side by side, each under its name.

Usage: contact_sheet.py [--columns N] OUT.png NAME=IMAGE.png [NAME=IMAGE.png ...]
(three to a row unless --columns says otherwise)
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

TITLE_INCHES = 0.3


def main(argv):
    columns = 3
    if len(argv) > 2 and argv[1] == "--columns":
        columns = int(argv[2])
        argv = argv[:1] + argv[3:]
    if len(argv) < 3 or columns < 1:
        sys.exit(__doc__)
    out = argv[1]
    views = [arg.split("=", 1) for arg in argv[2:]]
    images = [mpimg.imread(path) for _, path in views]
    height, width = images[0].shape[:2]
    rows = (len(images) + columns - 1) // columns
    dpi = 100
    cell_w, cell_h = width / dpi, height / dpi + TITLE_INCHES
    figure = plt.figure(figsize=(columns * cell_w, rows * cell_h), dpi=dpi)
    for index, ((name, _), image) in enumerate(zip(views, images)):
        row, column = divmod(index, columns)
        left = column * cell_w / (columns * cell_w)
        bottom = 1.0 - (row + 1) * cell_h / (rows * cell_h)
        axes = figure.add_axes([left, bottom, cell_w / (columns * cell_w),
                                (height / dpi) / (rows * cell_h)])
        axes.imshow(image, interpolation="nearest")
        axes.set_axis_off()
        figure.text(left + 0.5 / columns, bottom + (height / dpi + 0.05) / (rows * cell_h),
                    name, ha="center", va="bottom", fontsize=13)
    figure.savefig(out, dpi=dpi, facecolor="white")


if __name__ == "__main__":
    main(sys.argv)
