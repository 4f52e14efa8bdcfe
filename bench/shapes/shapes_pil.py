"""shapes.bas with Pillow (python3-pil): the same 100,000 shapes on an 800 x 600 image in the
same order. Prints a checksum of the same grid of pixels (palette indexes, as in rb)."""
from PIL import Image, ImageDraw

img = Image.new("P", (800, 600), 15)
d = ImageDraw.Draw(img)
seed = 1
for i in range(100000):
    seed = (seed * 1103515245 + 12345) % 2147483648
    x = seed % 800
    seed = (seed * 1103515245 + 12345) % 2147483648
    y = seed % 600
    seed = (seed * 1103515245 + 12345) % 2147483648
    w = 4 + seed % 120
    seed = (seed * 1103515245 + 12345) % 2147483648
    h = 4 + seed % 90
    c = i % 16
    k = i % 4
    filled = i % 8 >= 4
    if k == 0:
        d.ellipse([x, y, x + w, y + w], outline=c, fill=c if filled else None)
    elif k == 1:
        d.ellipse([x, y, x + w, y + h], outline=c, fill=c if filled else None)
    elif k == 2:
        d.rectangle([x, y, x + w, y + h], outline=c, fill=c if filled else None)
    else:
        d.line([x, y, x + w, y + h], fill=c, width=1)
px = img.load()
print(sum(px[x, y] for y in range(0, 600, 7) for x in range(0, 800, 5)))
