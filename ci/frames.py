"""The frames the browser wrote (PREFIX<n>.png, in the order of n) and the GIFs made of them, for the pictures
scripts (charpy_pictures.py, game_pictures.py, city_pictures.py). A GIF is written whole (a temporary file, then
renamed)."""
import glob
import os
import re


def frames_of(directory, who):
    def index(p):
        m = re.search(r"(\d+)\.png$", p)
        return int(m.group(1)) if m else -1

    files = sorted(glob.glob(os.path.join(directory, "*.png")), key=index)
    if not files:
        raise SystemExit(f"{who}: no PNG frames in {directory}")
    return files


def save_gif(images, path, fps, colors):
    from PIL import Image

    frames = [im.convert("RGB").convert("P", palette=Image.ADAPTIVE, colors=colors) for im in images]
    tmp = path + ".tmp.gif"
    frames[0].save(tmp, save_all=True, append_images=frames[1:], duration=int(round(1000 / fps)), loop=0, optimize=True)
    os.replace(tmp, path)


def animation(directory, path, fps, colors, who):
    """The GIF of a directory's frames; returns how many there were."""
    from PIL import Image

    files = frames_of(directory, who)
    save_gif([Image.open(f) for f in files], path, fps, colors)
    return len(files)
