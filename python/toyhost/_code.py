"""Shadertoys from code and data, without files: toyhost.from_code(image=..., common=...,
buffers={"A": ...}, channels={...}) writes the shadertoy as a Shadertoy export (the site's own
JSON form, API shape) and loads that, so it runs exactly as the same passes in an export or a
folder would; toyhost.load(dict) takes an export already parsed."""

import json

from . import _args as args

# The site's ids: Image's output, and Buffer A..D's outputs (which channels read them by).
IMAGE_OUTPUT = 37
BUFFER_IDS = {letter: 257 + n for n, letter in enumerate("ABCD")}
# A buffer read's sampler unless told otherwise: the site's defaults for a new buffer input.
BUFFER_SAMPLER = {"filter": "linear", "wrap": "clamp", "vflip": "true", "srgb": "false", "internal": "byte"}
FILTERS = ("nearest", "linear", "mipmap")
WRAPS = ("clamp", "repeat")


def _buffer_letter(name, text):
    letter = text.upper().removeprefix("BUFFER").strip()
    if letter not in BUFFER_IDS:
        raise args.usage(name, f"{text!r} is not a buffer: expected \"A\" .. \"D\"")
    return letter


def _channel_input(name, channel, spec):
    """One channel binding as an export input: "A".."D" (a buffer, linear and clamped as the site's
    default), "keyboard", {"buffer": "A", "filter": ..., "wrap": ...}, or an export input as the
    site writes it (a dict with "ctype"), passed on as it is."""
    if isinstance(spec, str):
        if spec.lower() == "keyboard":
            return {"id": 33, "ctype": "keyboard", "channel": channel,
                    "sampler": {"filter": "nearest", "wrap": "clamp", "vflip": "true", "srgb": "false",
                                "internal": "byte"}}
        spec = {"buffer": spec}
    if not isinstance(spec, dict):
        raise args.usage(name, f"iChannel{channel}: expected \"A\" .. \"D\", \"keyboard\" or a dict, got {spec!r}")
    if "ctype" in spec:
        return {**spec, "channel": channel}
    unknown = set(spec) - {"buffer", "filter", "wrap"}
    if unknown or "buffer" not in spec:
        raise args.usage(name, f"iChannel{channel}: expected {{\"buffer\": \"A\", \"filter\": ..., \"wrap\": ...}} "
                               f"or an export input with \"ctype\", got {spec!r}")
    letter = _buffer_letter(name, args.text(name, spec["buffer"]))
    sampler = dict(BUFFER_SAMPLER)
    for key, allowed in (("filter", FILTERS), ("wrap", WRAPS)):
        if key in spec:
            if spec[key] not in allowed:
                raise args.usage(name, f"iChannel{channel}: {key} must be one of {', '.join(allowed)}, "
                                       f"got {spec[key]!r}")
            sampler[key] = spec[key]
    return {"id": BUFFER_IDS[letter], "ctype": "buffer", "channel": channel, "sampler": sampler}


def is_array(spec):
    """A channel source that is pixels (a numpy array or anything numpy takes as one, but not a
    str, dict or number), which a session shows through Session.set_channel."""
    return hasattr(spec, "__array_interface__") or hasattr(spec, "__array__")


def _pass_channels(name, bindings, arrays=None, owner="Image"):
    if bindings is None:
        return []
    if not isinstance(bindings, dict):
        raise args.usage(name, f"expected {{channel: source}}, got {bindings!r}")
    inputs = []
    for key, spec in bindings.items():
        text = str(key).removeprefix("iChannel")
        if not text.isdigit() or int(text) > 3:
            raise args.usage(name, f"{key!r} is not a channel: expected 0..3 or \"iChannel0\" .. \"iChannel3\"")
        if is_array(spec):  # left unbound in the export; the session shows the array there
            if arrays is not None:
                arrays[(owner, int(text))] = spec
            continue
        inputs.append(_channel_input(name, int(text), spec))
    return inputs


def export_of_code(image, common=None, buffers=None, channels=None, name="code", arrays=None):
    """The export dict from_code loads (also useful to save: json.dump it and the site's format
    and toyhost's `import` read it). Channels given as arrays are left unbound in it and put in
    ``arrays`` ({(pass name, channel): array}) when given."""
    image = args.text("image", image)
    buffers = buffers or {}
    if not isinstance(buffers, dict):
        raise args.usage("buffers", f"expected {{\"A\": code, ...}}, got {buffers!r}")
    channels = channels or {}
    if not isinstance(channels, dict):
        raise args.usage("channels", f"expected {{\"Image\" or \"A\"..\"D\": {{channel: source}}}}, got {channels!r}")
    by_pass = {}
    for key, bindings in channels.items():
        text = args.text("channels", key)
        owner = "Image" if text.lower() == "image" else _buffer_letter("channels", text)
        if owner != "Image" and owner not in {_buffer_letter("buffers", b) for b in buffers}:
            raise args.usage("channels", f"{text!r}: the shadertoy has no such buffer (give its code in buffers)")
        by_pass[owner] = _pass_channels("channels", bindings, arrays,
                                        "Image" if owner == "Image" else f"Buffer {owner}")
    passes = []
    if common is not None:
        passes.append({"inputs": [], "outputs": [], "code": args.text("common", common), "name": "Common",
                       "type": "common"})
    for key in sorted(buffers, key=lambda k: _buffer_letter("buffers", args.text("buffers", k))):
        letter = _buffer_letter("buffers", key)
        passes.append({"inputs": by_pass.get(letter, []), "outputs": [{"id": BUFFER_IDS[letter], "channel": 0}],
                       "code": args.text("buffers", buffers[key]), "name": f"Buffer {letter}", "type": "buffer"})
    passes.append({"inputs": by_pass.get("Image", []), "outputs": [{"id": IMAGE_OUTPUT, "channel": 0}],
                   "code": image, "name": "Image", "type": "image"})
    return {"Shader": {"ver": "0.1", "info": {"id": "", "name": args.text("name", name), "username": ""},
                       "renderpass": passes}}


def dumps(document):
    try:
        return json.dumps(document)
    except (TypeError, ValueError) as error:
        raise args.usage("shadertoy", f"the dict is not JSON data: {error}") from None
