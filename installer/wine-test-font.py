"""Test prefix only, never shipped: a copy of a free font whose family name is "Arial".

WPF ends the process (Invariant.FailFast in TypefaceMap) when text falls back to its last-resort family and no font
named "Arial" exists (dotnet/wpf#4464); a bare Wine prefix has none. wine-smoke.sh puts Liberation Sans, which has
Arial's metrics, under that name into its throwaway prefix.

    wine-test-font.py SOURCE.ttf DEST.ttf FAMILY STYLE     e.g. LiberationSans-Bold.ttf arialbd.ttf Arial Bold
Prints the font's full name, the value Windows lists it under in the registry's Fonts key.
"""
import sys

from fontTools.ttLib import TTFont

source, dest, family, style = sys.argv[1:5]
font = TTFont(source)
full = family if style == "Regular" else f"{family} {style}"
postscript = family.replace(" ", "") + "-" + style.replace(" ", "")
for record in font["name"].names:
    # 1/16 family, 2/17 style, 4 full name, 6 PostScript name, 3 unique id (OpenType 'name' table ids).
    if record.nameID in (1, 16):
        record.string = family
    elif record.nameID in (2, 17):
        record.string = style
    elif record.nameID == 4:
        record.string = full
    elif record.nameID == 6:
        record.string = postscript
    elif record.nameID == 3:
        record.string = full + " (Wine test copy of Liberation)"
font.save(dest)
print(full)
