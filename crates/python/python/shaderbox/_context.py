"""Contexts, programs, uniforms, buffers, vertex arrays, textures and the
fixed-function state, over the native ``RawContext``."""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _gl
from . import _shaderbox
from ._errors import CompileError, Diagnostics, Error, GLError, LinkError, _diagnostics
from ._image import Image

ArrayLike = Any


def _check_gl(raw: Any, during: str) -> None:
    code = raw.get_error()
    if code != _gl.NO_ERROR:
        raise GLError(code, _gl.error_name(code), during)


def _floats(value: ArrayLike, n: int, what: str) -> List[float]:
    a = _numeric(value, what)
    if a.size != n:
        raise ValueError(f"{what} needs {n} numbers, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{what} must be finite, got {a.tolist()}")
    return [float(x) for x in a.reshape(-1)]


def _numeric(value: ArrayLike, what: str) -> np.ndarray:
    try:
        a = np.asarray(value)
    except Exception as e:  # ragged sequences
        raise ValueError(f"{what}: {value!r} is not an array of numbers ({e})") from None
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{what} needs real numbers, got dtype {a.dtype} ({value!r})")
    return a


# ---- uniforms ----------------------------------------------------------------


@dataclass(frozen=True)
class Uniform:
    """An active uniform: ``type`` is its GLSL type (``"vec3"``),
    ``array_length`` its array size (``None`` if not an array), ``shape``
    the numpy shape a value must have, ``location`` its GL location."""

    name: str
    type: str
    array_length: Optional[int]
    shape: Tuple[int, ...]
    location: int
    kind: str  # "float", "int", "uint", "bool" or "sampler"

    @property
    def element_shape(self) -> Tuple[int, ...]:
        return self.shape[1:] if self.array_length is not None else self.shape

    def _describe(self) -> str:
        return f"{self.type}[{self.array_length}]" if self.array_length is not None else self.type


@dataclass(frozen=True)
class Attribute:
    """An active vertex attribute; built-in ones (``gl_Vertex``,
    ``gl_Color``, ``gl_MultiTexCoord0``...) have ``location`` -1."""

    name: str
    type: str
    location: int

    @property
    def builtin(self) -> bool:
        return self.name.startswith("gl_")

    @property
    def integer(self) -> bool:
        """Whether the attribute is ``int``/``ivecN``/``uint``/``uvecN``:
        fed unconverted (glVertexAttribIPointer), from an integer format."""
        kind = next((k for g, k, _ in _gl.TYPES.values() if g == self.type), "float")
        return kind in ("int", "uint")


@dataclass(frozen=True)
class BlockMember:
    """A member of a uniform block as the program lays it out (std140 for
    ``layout(std140)`` blocks): ``offset`` in bytes from the block's start,
    ``array_stride`` between array elements, ``matrix_stride`` between a
    matrix's columns (rows if ``row_major``)."""

    name: str
    type: str
    array_length: Optional[int]
    shape: Tuple[int, ...]
    kind: str
    offset: int
    array_stride: int
    matrix_stride: int
    row_major: bool

    @property
    def element_shape(self) -> Tuple[int, ...]:
        return self.shape[1:] if self.array_length is not None else self.shape

    def _describe(self) -> str:
        return f"{self.type}[{self.array_length}]" if self.array_length is not None else self.type


class UniformBlock:
    """An active uniform block of a :class:`Program` (``prog["Block"]`` or
    ``prog.uniform_blocks["Block"]``).

    The block reads its members from the buffer bound to its binding
    point: set :attr:`binding`, write the data into a :class:`Buffer`
    (:meth:`pack` lays values out at the member offsets the program uses)
    and bind it with :meth:`Buffer.bind_to_uniform_block`::

        block = prog["Light"]
        block.binding = 0
        ubo = ctx.buffer(block.pack({"color": (1, 0, 0, 1), "dir": (0, 0, 1)}))
        ubo.bind_to_uniform_block(0)
    """

    def __init__(self, program: "Program", name: str, index: int, size: int, members: Dict[str, BlockMember]):
        self.program = program
        self.name = name
        #: The block index (glGetUniformBlockIndex).
        self.index = index
        #: GL_UNIFORM_BLOCK_DATA_SIZE: the bytes a buffer must hold.
        self.size = size
        #: The members by the names GL gives them (``"Block.member"`` for
        #: a block with an instance name).
        self.members = members

    @property
    def binding(self) -> int:
        """The uniform-buffer binding point the block reads
        (glUniformBlockBinding; 0 until set)."""
        raw = self.program.ctx._raw
        for name, _index, binding, _size, _members in raw.uniform_blocks(self.program.glo):
            if name == self.name:
                return int(binding)
        return 0

    @binding.setter
    def binding(self, binding: int) -> None:
        raw = self.program.ctx._raw
        n = _max_uniform_bindings(raw)
        if not isinstance(binding, (int, np.integer)) or isinstance(binding, bool) or not 0 <= int(binding) < n:
            raise ValueError(f"uniform block {self.name!r}: binding points are 0-{n - 1}, got {binding!r}")
        raw.uniform_block_binding(self.program.glo, self.index, int(binding))
        _check_gl(raw, f"setting the binding of uniform block {self.name!r}")

    def _member(self, key: str) -> BlockMember:
        m = self.members.get(key) or self.members.get(f"{self.name}.{key}")
        if m is None:
            known = ", ".join(sorted(self.members)) or "none"
            raise KeyError(f"uniform block {self.name!r} has no active member {key!r} (its members: {known})")
        return m

    def pack(self, values: Dict[str, Any], into: Optional[bytearray] = None) -> bytes:
        """``values`` (member name -> value, shaped as for uniforms) laid
        out as the block's bytes (:attr:`size` of them; members not given
        are zero, or keep their bytes from ``into``). Names are the
        members' (``"color"``, or ``"Block.color"`` / ``"color"`` for a
        block with an instance name)."""
        out = bytearray(self.size) if into is None else bytearray(into)
        if len(out) < self.size:
            raise ValueError(f"uniform block {self.name!r} is {self.size} bytes, `into` holds {len(out)}")
        for key, value in values.items():
            m = self._member(key)
            _pack_member(out, m, value, f"member {key!r} of uniform block {self.name!r} ({m._describe()})")
        return bytes(out)

    def __repr__(self) -> str:
        return f"<shaderbox.UniformBlock {self.name!r}: {self.size} bytes, members {sorted(self.members)}>"


def _max_uniform_bindings(raw: Any) -> int:
    v = raw.get_integerv(_gl.MAX_UNIFORM_BUFFER_BINDINGS)
    return int(v[0]) if v else 0


_BLOCK_DTYPES = {"float": np.dtype("<f4"), "int": np.dtype("<i4"), "uint": np.dtype("<u4"), "bool": np.dtype("<u4")}


def _pack_member(out: bytearray, m: BlockMember, value: Any, what: str) -> None:
    """Writes ``value`` into ``out`` at ``m``'s offsets and strides."""
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{what}: got {type(value).__name__} {value!r}")
    a = _numeric(value, what)
    elem = m.element_shape
    n_elem = _size(elem)
    n = m.array_length if m.array_length is not None else 1
    if a.shape == elem or (m.array_length is None and a.ndim == 1 and a.size == n_elem):
        count = 1
    elif m.array_length is not None and a.ndim == len(elem) + 1 and a.shape[1:] == elem and 1 <= a.shape[0] <= n:
        count = a.shape[0]
    elif m.array_length is not None and a.ndim == 1 and a.size % max(1, n_elem) == 0 and 1 <= a.size // max(1, n_elem) <= n:
        count = a.size // max(1, n_elem)
    else:
        want = (n,) + elem if m.array_length is not None else elem
        raise ValueError(f"{what}: expected shape {want}, got shape {a.shape}")
    flat = a.reshape(count, n_elem)
    if m.kind == "float":
        if not np.all(np.isfinite(flat)):
            raise ValueError(f"{what}: values must be finite")
    elif a.dtype.kind == "f":
        raise TypeError(f"{what} takes integers, got {a.dtype} values; convert with .astype(int)")
    elif m.kind == "int" and (np.any(flat < -(2**31)) or np.any(flat >= 2**31)):
        raise ValueError(f"{what}: values must fit in 32 bits, got {flat.tolist()}")
    elif m.kind == "uint" and (np.any(flat < 0) or np.any(flat >= 2**32)):
        raise ValueError(f"{what}: values must be 0 to 2**32-1, got {flat.tolist()}")
    if m.kind == "bool":
        flat = flat != 0
    words = flat.astype(_BLOCK_DTYPES.get(m.kind, np.dtype("<f4")))
    for i in range(count):
        base = m.offset + i * m.array_stride
        if len(elem) == 2:
            rows, cols = elem
            mat = words[i].reshape(rows, cols)
            # Each column (each row when row-major) is a vector at its stride.
            vectors = mat if m.row_major else mat.T
            for k, vec in enumerate(vectors):
                start = base + k * m.matrix_stride
                out[start : start + 4 * vec.size] = vec.tobytes()
        else:
            out[base : base + 4 * n_elem] = words[i].tobytes()


class Program:
    """A linked GLSL program (made by :meth:`Context.program`).

    ``prog["name"] = value`` sets a uniform: a number, tuple, list or numpy
    array of the uniform's shape (``vec3``: 3 values; ``mat4``: 4x4 in
    mathematical row/column order, i.e. ``m[row, col]``; ``float[8]``: 8
    values; a flat sequence of the right length is accepted too).
    ``sampler2D`` uniforms take a texture unit or a :class:`Texture`.
    Unknown names raise ``KeyError``, wrong shapes ``ValueError``, wrong
    dtypes (floats for an ``int``, strings...) ``TypeError``.
    ``prog["name"]`` reads the value back.

    ``prog["Block"]`` is the :class:`UniformBlock` named ``Block`` (also in
    :attr:`uniform_blocks`); the members of uniform blocks are not set
    with ``prog[...]`` but read from a buffer (:meth:`UniformBlock.pack`,
    :meth:`Buffer.bind_to_uniform_block`).
    """

    def __init__(self, ctx: "Context", name: int, warnings: Diagnostics):
        self.ctx = ctx
        self.glo = name
        #: Warnings from compiling and linking (a :class:`Diagnostics`).
        self.warnings = warnings
        raw = ctx._raw
        self.uniforms: Dict[str, Uniform] = {}
        for uname, size, ty, loc, block in raw.active_uniforms(name):
            if block >= 0:
                continue  # a block member: in uniform_blocks
            glsl, kind, shape = _gl.TYPES.get(ty, (f"0x{ty:04x}", "float", ()))
            base = uname[:-3] if uname.endswith("[0]") else uname
            array = size if uname.endswith("[0]") else None
            full = ((size,) + shape) if array is not None else shape
            self.uniforms[base] = Uniform(base, glsl, array, full, loc, kind)
        #: The active uniform blocks by name (:class:`UniformBlock`).
        self.uniform_blocks: Dict[str, UniformBlock] = {}
        self._block_of_member: Dict[str, str] = {}
        for bname, index, _binding, bsize, members in raw.uniform_blocks(name):
            mems: Dict[str, BlockMember] = {}
            for mname, ty, size, offset, astride, mstride, row_major in members:
                glsl, kind, shape = _gl.TYPES.get(ty, (f"0x{ty:04x}", "float", ()))
                base = mname[:-3] if mname.endswith("[0]") else mname
                array = size if mname.endswith("[0]") else None
                full = ((size,) + shape) if array is not None else shape
                mems[base] = BlockMember(base, glsl, array, full, kind, offset, astride, mstride, bool(row_major))
                self._block_of_member[base] = bname
            self.uniform_blocks[bname] = UniformBlock(self, bname, index, bsize, mems)
        self.attributes: Dict[str, Attribute] = {}
        for aname, ty, loc in raw.active_attributes(name):
            glsl = _gl.TYPES.get(ty, (f"0x{ty:04x}",))[0]
            self.attributes[aname] = Attribute(aname, glsl, loc)

    def _lookup(self, name: str) -> Tuple[Uniform, int, Optional[int]]:
        """The uniform, the location to start at, and how many elements
        are left from there (None: not an array)."""
        if not isinstance(name, str):
            raise TypeError(f"uniform names are strings, not {type(name).__name__}")
        self._refuse_block_member(name)
        u = self.uniforms.get(name)
        if u is not None:
            return u, u.location, u.array_length
        m = re.fullmatch(r"(.+)\[(\d+)\]", name)
        if m and m.group(1) in self.uniforms:
            u = self.uniforms[m.group(1)]
            i = int(m.group(2))
            if u.array_length is None or i >= u.array_length:
                raise KeyError(f"uniform {name!r}: {u.name} is {u._describe()}, index {i} is out of range")
            loc = self.ctx._raw.uniform_location(self.glo, name)
            return u, loc, None
        known = ", ".join(sorted(self.uniforms)) or "none"
        raise KeyError(f"the program has no active uniform {name!r} (its uniforms: {known})")

    def _refuse_block_member(self, name: str) -> None:
        base = re.sub(r"\[\d+\]$", "", name)
        block = self._block_of_member.get(base)
        if block is not None:
            raise TypeError(
                f"{name!r} is a member of uniform block {block!r}, whose values come from a buffer, not from "
                f"prog[...]: write them into a Buffer (prog[{block!r}].pack({{...}}) lays them out), bind it with "
                f"buffer.bind_to_uniform_block(binding) and set prog[{block!r}].binding = binding"
            )

    def __contains__(self, name: object) -> bool:
        return isinstance(name, str) and (name in self.uniforms or name in self.uniform_blocks)

    def __setitem__(self, name: str, value: Any) -> None:
        if isinstance(name, str) and name in self.uniform_blocks:
            raise TypeError(
                f"{name!r} is a uniform block: set its binding point with prog[{name!r}].binding = n and bind "
                "a buffer holding its data with buffer.bind_to_uniform_block(n)"
            )
        u, loc, left = self._lookup(name)
        raw = self.ctx._raw
        raw.use_program(self.glo)
        elem = u.element_shape
        if u.kind == "sampler" and isinstance(value, Texture):
            value = value.unit
        if isinstance(value, (str, bytes)):
            raise TypeError(f"uniform {name!r} is {u._describe()}: got {type(value).__name__} {value!r}")
        a = _numeric(value, f"uniform {name!r} ({u._describe()})")
        count = self._count(name, u, a, elem, left)
        flat = a.reshape(-1)
        what = f"uniform {name!r} ({u._describe()})"
        if u.kind == "float":
            if not np.all(np.isfinite(flat)):
                raise ValueError(f"{what}: values must be finite")
            vals = [float(x) for x in flat.astype(np.float32)]
            if len(elem) == 2:
                rows, cols = elem
                raw.uniform_matrix(loc, cols, rows, count, vals)
            else:
                raw.uniform_f(loc, max(1, _size(elem)), count, vals)
        else:
            if a.dtype.kind == "f":
                hint = "a texture unit (int) or a Texture" if u.kind == "sampler" else "integers"
                raise TypeError(f"{what} takes {hint}, got {a.dtype} values; convert with int() or .astype(int)")
            if u.kind == "sampler":
                n_units = _shaderbox.MAX_TEXTURE_UNITS
                if np.any(flat < 0) or np.any(flat >= n_units):
                    raise ValueError(f"{what}: texture units are 0-{n_units - 1}, got {flat.tolist()}")
            if u.kind == "uint":
                if np.any(flat < 0) or np.any(flat >= 2**32):
                    raise ValueError(f"{what}: values must be 0 to 2**32-1, got {flat.tolist()}")
                raw.uniform_u(loc, max(1, _size(elem)), count, [int(x) for x in flat])
                _check_gl(raw, f"setting uniform {name!r}")
                return
            if np.any(flat < -(2**31)) or np.any(flat >= 2**31):
                raise ValueError(f"{what}: values must fit in 32 bits, got {flat.tolist()}")
            raw.uniform_i(loc, max(1, _size(elem)), count, [int(x) for x in flat])
        _check_gl(raw, f"setting uniform {name!r}")

    @staticmethod
    def _count(name: str, u: Uniform, a: np.ndarray, elem: Tuple[int, ...], left: Optional[int]) -> int:
        n_elem = _size(elem)
        what = f"uniform {name!r} is {u._describe()}"
        if left is None:
            if a.shape == elem or (a.ndim == 1 and a.size == n_elem and len(elem) > 0):
                return 1
            want = f"shape {elem}" if elem else "a single number"
            if len(elem) > 0:
                want += f" (or {n_elem} values)"
            raise ValueError(f"{what}: expected {want}, got shape {a.shape}")
        # An array (or the rest of one, from an element on).
        if a.shape[1:] == elem and a.ndim == len(elem) + 1 and 1 <= a.shape[0] <= left:
            return int(a.shape[0])
        if a.ndim == 1 and a.size % max(1, n_elem) == 0 and 1 <= a.size // max(1, n_elem) <= left:
            return a.size // max(1, n_elem)
        if a.shape == elem and elem:
            return 1
        if a.ndim == 0 and not elem:
            return 1
        raise ValueError(f"{what}: expected shape {(left,) + elem} (or fewer elements), got shape {a.shape}")

    def __getitem__(self, name: str) -> Any:
        if isinstance(name, str) and name in self.uniform_blocks:
            return self.uniform_blocks[name]
        u, loc, left = self._lookup(name)
        raw = self.ctx._raw
        n = left if left is not None else 1
        base = u.name
        vals: List[List[Any]] = []
        for i in range(n):
            el_loc = loc if (i == 0) else raw.uniform_location(self.glo, f"{base}[{i}]")
            if u.kind == "float":
                vals.append(raw.get_uniformf(self.glo, el_loc))
            elif u.kind == "uint":
                vals.append(raw.get_uniformu(self.glo, el_loc))
            else:
                vals.append(raw.get_uniformi(self.glo, el_loc))
        _check_gl(raw, f"reading uniform {name!r}")
        dtype = {"float": np.float32, "bool": np.bool_, "uint": np.uint32}.get(u.kind, np.int32)
        out: np.ndarray = np.asarray(vals, dtype=dtype)
        elem = u.element_shape
        if len(elem) == 2:
            # GL returns matrices column by column.
            rows, cols = elem
            out = out.reshape((n, cols, rows)).transpose(0, 2, 1)
        else:
            out = out.reshape((n,) + elem)
        if left is None:
            out = out[0]
            if out.ndim == 0:
                return out.item()
        return out

    def __repr__(self) -> str:
        blocks = f", uniform blocks {sorted(self.uniform_blocks)}" if self.uniform_blocks else ""
        return f"<shaderbox.Program {self.glo}: uniforms {sorted(self.uniforms)}{blocks}, attributes {sorted(self.attributes)}>"


def _size(shape: Tuple[int, ...]) -> int:
    n = 1
    for s in shape:
        n *= s
    return n


# ---- buffers and vertex arrays -----------------------------------------------

_FORMATS = {
    "f": (_gl.FLOAT, 4, "f"),
    "f4": (_gl.FLOAT, 4, "f"),
    "f8": (_gl.DOUBLE, 8, "f"),
    "d": (_gl.DOUBLE, 8, "f"),
    "i": (_gl.INT, 4, "i"),
    "i4": (_gl.INT, 4, "i"),
    "i2": (_gl.SHORT, 2, "i"),
    "i1": (_gl.BYTE, 1, "i"),
    "u": (_gl.UNSIGNED_INT, 4, "u"),
    "u4": (_gl.UNSIGNED_INT, 4, "u"),
    "u2": (_gl.UNSIGNED_SHORT, 2, "u"),
    "u1": (_gl.UNSIGNED_BYTE, 1, "u"),
}
# GL type -> "f" (float) or "i"/"u" (integer).
_FORMATS_KIND = {gl_type: kind for gl_type, _, kind in _FORMATS.values()}
_NUMPY_OF: Dict[Tuple[int, int], np.dtype] = {
    (_gl.FLOAT, 4): np.dtype("<f4"),
    (_gl.DOUBLE, 8): np.dtype("<f8"),
    (_gl.INT, 4): np.dtype("<i4"),
    (_gl.SHORT, 2): np.dtype("<i2"),
    (_gl.BYTE, 1): np.dtype("i1"),
    (_gl.UNSIGNED_INT, 4): np.dtype("<u4"),
    (_gl.UNSIGNED_SHORT, 2): np.dtype("<u2"),
    (_gl.UNSIGNED_BYTE, 1): np.dtype("u1"),
}


@dataclass(frozen=True)
class _Field:
    components: int
    gl_type: int
    size: int  # bytes per component
    normalized: bool
    padding: bool
    # glVertexAttribDivisor: 0 per vertex, 1 per instance.
    divisor: int = 0


def parse_format(fmt: str) -> List[_Field]:
    """Parses a vertex format such as ``"3f 4f"``, ``"2f 4u1n"`` or
    ``"3f 4x"``: per field, a component count, a type (``f``/``f4``
    float32, ``f8`` float64, ``i``/``i4``, ``i2``, ``i1``, ``u``/``u4``,
    ``u2``, ``u1``), ``n`` to normalize integers to 0-1 (or -1-1), or
    ``x`` for padding bytes. A trailing ``/i`` makes every field of the
    format per instance (the next element each instance, divisor 1),
    ``/r`` per render (element 0 for every instance); ``/v`` (the
    default) is per vertex."""
    if not isinstance(fmt, str) or not fmt.strip():
        raise ValueError(f"vertex format {fmt!r} is empty: write e.g. '3f' or '3f 4f'")
    divisor = 0
    m = re.fullmatch(r"(.*?)\s*/\s*(\S*)\s*", fmt)
    body = fmt
    if m:
        rate = m.group(2)
        if rate not in ("v", "i", "r"):
            raise ValueError(
                f"vertex format {fmt!r}: {'/' + rate!r} is not a rate ('/v' per vertex, '/i' per instance, '/r' per render)"
            )
        divisor = {"v": 0, "i": 1, "r": _gl.PER_RENDER_DIVISOR}[rate]
        body = m.group(1)
        if not body.strip():
            raise ValueError(f"vertex format {fmt!r} has a rate but no fields: write e.g. '3f/i'")
    fields = []
    for tok in body.split():
        m = re.fullmatch(r"(\d*)(x|f8|f4|f|d|i4|i2|i1|i|u4|u2|u1|u)(n?)", tok)
        if not m:
            raise ValueError(
                f"vertex format {fmt!r}: {tok!r} is not COUNT+TYPE (types f, f4, f8, i, i1, i2, i4, u, u1, u2, u4; "
                "'n' after an integer type normalizes; 'x' is a padding byte)"
            )
        count = int(m.group(1) or "1")
        kind, norm = m.group(2), m.group(3) == "n"
        if kind == "x":
            if norm:
                raise ValueError(f"vertex format {fmt!r}: padding ({tok!r}) cannot be normalized")
            fields.append(_Field(count, 0, 1, False, True, divisor))
            continue
        if not 1 <= count <= 4:
            raise ValueError(f"vertex format {fmt!r}: {tok!r} has {count} components; attributes have 1-4")
        gl_type, size, k = _FORMATS[kind]
        if norm and k == "f":
            raise ValueError(f"vertex format {fmt!r}: only integer types can be normalized ({tok!r})")
        fields.append(_Field(count, gl_type, size, norm, False, divisor))
    return fields


class Buffer:
    """Vertex or index data in a GL buffer object (made by
    :meth:`Context.buffer`). ``dtype`` is the numpy dtype it was made from
    (``None`` for raw bytes); ``nbytes`` its size."""

    def __init__(self, ctx: "Context", data: Any):
        self.ctx = ctx
        self.dtype: Optional[np.dtype] = None
        self.shape: Tuple[int, ...] = ()
        if isinstance(data, (bytes, bytearray, memoryview)):
            raw_bytes = bytes(data)
        else:
            a = np.asarray(data)
            if a.dtype.kind not in "biuf":
                raise TypeError(f"buffer data must be numbers (a numeric numpy array or bytes), got dtype {a.dtype}")
            if a.dtype.byteorder == ">":
                a = a.astype(a.dtype.newbyteorder("<"))
            a = np.ascontiguousarray(a)
            self.dtype = a.dtype
            self.shape = a.shape
            raw_bytes = a.tobytes()
        self.nbytes = len(raw_bytes)
        self.glo = ctx._raw.create_buffer(raw_bytes)
        _check_gl(ctx._raw, "creating a buffer")

    def release(self) -> None:
        """Deletes the GL buffer object."""
        if self.glo:
            self.ctx._raw.delete_buffer(self.glo)
            self.glo = 0

    def _range(self, offset: int, size: Optional[int], what: str) -> Tuple[int, int]:
        for n, v in (("offset", offset), ("size", size)):
            if v is not None and (not isinstance(v, (int, np.integer)) or isinstance(v, bool) or v < 0):
                raise ValueError(f"{what}: {n} must be a non-negative int, got {v!r}")
        offset = int(offset)
        size = self.nbytes - offset if size is None else int(size)
        if offset + size > self.nbytes or size < 0:
            raise ValueError(f"{what}: bytes {offset}-{offset + size} are past the buffer's {self.nbytes}")
        return offset, size

    def write(self, data: Any, offset: int = 0) -> None:
        """Replaces bytes from ``offset`` with ``data`` (bytes or a numeric
        array; glBufferSubData). The buffer keeps its size."""
        if isinstance(data, (bytes, bytearray, memoryview)):
            raw_bytes = bytes(data)
        else:
            a = _numeric(data, "buffer data")
            if a.dtype.byteorder == ">":
                a = a.astype(a.dtype.newbyteorder("<"))
            raw_bytes = np.ascontiguousarray(a).tobytes()
        offset, _ = self._range(offset, len(raw_bytes), "Buffer.write")
        self.ctx._raw.buffer_sub_data(self.glo, offset, raw_bytes)
        _check_gl(self.ctx._raw, "writing a buffer")

    def read(self, size: Optional[int] = None, offset: int = 0) -> bytes:
        """``size`` bytes (default: to the end) from ``offset``."""
        offset, size = self._range(offset, size, "Buffer.read")
        data = self.ctx._raw.get_buffer_sub_data(self.glo, offset, size)
        _check_gl(self.ctx._raw, "reading a buffer")
        return bytes(data)

    def bind_to_uniform_block(self, binding: int = 0, offset: int = 0, size: Optional[int] = None) -> None:
        """Binds the buffer (bytes ``offset`` to ``offset + size``; default:
        all of it) to uniform-buffer binding point ``binding``
        (glBindBufferBase / glBindBufferRange on GL_UNIFORM_BUFFER): the
        uniform blocks whose :attr:`UniformBlock.binding` is ``binding``
        read their members from it."""
        raw = self.ctx._raw
        if self.ctx.version < (3, 1):
            raise RuntimeError(
                f"uniform buffers are OpenGL 3.1; this context is {self.ctx.version[0]}.{self.ctx.version[1]}: "
                "create it with version=(3, 3)"
            )
        n = _max_uniform_bindings(raw)
        if not isinstance(binding, (int, np.integer)) or isinstance(binding, bool) or not 0 <= int(binding) < n:
            raise ValueError(f"uniform buffer binding points are 0-{n - 1}, got {binding!r}")
        if offset == 0 and size is None:
            raw.bind_uniform_buffer(int(binding), self.glo, None)
        else:
            offset, size = self._range(offset, size, "bind_to_uniform_block")
            align = raw.get_integerv(_gl.UNIFORM_BUFFER_OFFSET_ALIGNMENT)
            a = int(align[0]) if align else 1
            if offset % a:
                raise ValueError(f"bind_to_uniform_block: offset {offset} is not a multiple of {a} (GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT)")
            if size == 0:
                raise ValueError("bind_to_uniform_block: the range is empty")
            raw.bind_uniform_buffer(int(binding), self.glo, (offset, size))
        _check_gl(raw, f"binding a buffer to uniform binding point {binding}")

    def __repr__(self) -> str:
        return f"<shaderbox.Buffer {self.glo}: {self.nbytes} bytes{'' if self.dtype is None else ', ' + str(self.dtype)}>"


class VertexArray:
    """A program plus the buffers that feed its attributes (made by
    :meth:`Context.vertex_array`); :meth:`render` draws."""

    def __init__(
        self,
        ctx: "Context",
        program: Program,
        content: Sequence[Tuple[Any, ...]],
        index_buffer: Any = None,
    ):
        if not isinstance(program, Program):
            raise TypeError(f"vertex_array needs a Program first, got {type(program).__name__}")
        self.ctx = ctx
        self.program = program
        # name, field, buffer, stride, offset, integer
        self._bindings: List[Tuple[str, _Field, int, int, int, bool]] = []
        counts = []
        # Instances the per-instance buffers can feed (None: no limit).
        instance_limits: List[int] = []
        seen = set()
        if isinstance(content, tuple) and content and isinstance(content[1] if len(content) > 1 else None, str):
            content = [content]
        for item in content:
            if not isinstance(item, (tuple, list)) or len(item) < 3:
                raise ValueError(
                    f"vertex_array content items are (buffer, format, name, ...), got {item!r}"
                )
            buf, fmt, names = item[0], item[1], list(item[2:])
            if not isinstance(buf, Buffer):
                buf = ctx.buffer(buf)
            if buf.ctx is not ctx:
                raise ValueError("the buffer belongs to another Context")
            fields = parse_format(fmt)
            attrs = [f for f in fields if not f.padding]
            if len(attrs) != len(names):
                raise ValueError(
                    f"vertex format {fmt!r} has {len(attrs)} attribute(s) but {len(names)} name(s) were given: {names}"
                )
            for f in attrs:
                want: np.dtype = _NUMPY_OF[(f.gl_type, f.size)]
                if buf.dtype is not None and buf.dtype != want:
                    raise TypeError(
                        f"vertex format {fmt!r} reads {want} but the buffer for {names} holds {buf.dtype}; "
                        f"convert with .astype(np.{want.name}) or change the format"
                    )
            stride = sum(f.components * f.size for f in fields)
            offset = 0
            it = iter(names)
            for f in fields:
                if not f.padding:
                    name = next(it)
                    if not isinstance(name, str):
                        raise TypeError(f"attribute names are strings, got {name!r}")
                    if name in seen:
                        raise ValueError(f"attribute {name!r} is given twice")
                    seen.add(name)
                    builtin = name.startswith("gl_")
                    if builtin and ctx.profile == "core":
                        raise ValueError(
                            f"{name!r} is a built-in attribute of the compatibility profile; a core context feeds "
                            "the shader's own `in` attributes (declare e.g. `layout(location = 0) in vec3 pos;`)"
                        )
                    if builtin and f.divisor:
                        raise ValueError(f"built-in attribute {name!r} cannot be per instance ({fmt!r})")
                    if not builtin and name not in program.attributes:
                        known = ", ".join(sorted(program.attributes)) or "none"
                        raise KeyError(f"the program has no active attribute {name!r} (its attributes: {known})")
                    integer = not builtin and program.attributes[name].integer
                    if integer and (_FORMATS_KIND[f.gl_type] == "f" or f.normalized):
                        a = program.attributes[name]
                        raise TypeError(
                            f"attribute {name!r} is {a.type}, an integer attribute: feed it an integer format "
                            f"('i', 'i2', 'i1', 'u', 'u2', 'u1', without 'n'), not {fmt!r}; its values reach the "
                            "shader unconverted"
                        )
                    self._bindings.append((name, f, buf.glo, stride, offset, integer))
                offset += f.components * f.size
            elements = buf.nbytes // stride if stride else 0
            divisor = fields[0].divisor
            if divisor == 0:
                counts.append(elements)
            elif divisor == _gl.PER_RENDER_DIVISOR:
                instance_limits.append(2**31 - 1 if elements else 0)
            else:
                instance_limits.append(min(elements * divisor, 2**31 - 1))
        #: Vertices available in every per-vertex buffer (what render()
        #: draws by default); None when no buffer is per vertex (the
        #: shader works from gl_VertexID: pass render(vertices=...)).
        self.vertices: Optional[int] = min(counts) if counts else None
        #: Instances the per-instance buffers hold (None: no such buffer).
        self.instances: Optional[int] = min(instance_limits) if instance_limits else None
        self.index_buffer: Optional[Buffer] = None
        self._index_type = 0
        if index_buffer is not None:
            if not isinstance(index_buffer, Buffer):
                a = np.asarray(index_buffer)
                if a.dtype.kind not in "iub":
                    raise TypeError(f"indices must be integers, got dtype {a.dtype}")
                if a.size and (a.min() < 0 or a.max() >= 2**32):
                    raise ValueError("indices must be 0 to 2**32-1")
                if a.dtype not in (np.uint8, np.uint16, np.uint32):
                    a = a.astype(np.uint32)
                index_buffer = ctx.buffer(a.reshape(-1))
            types = {np.dtype("u1"): _gl.UNSIGNED_BYTE, np.dtype("<u2"): _gl.UNSIGNED_SHORT, np.dtype("<u4"): _gl.UNSIGNED_INT}
            if index_buffer.dtype not in types:
                raise TypeError(f"an index buffer holds uint8, uint16 or uint32, not {index_buffer.dtype}")
            self.index_buffer = index_buffer
            self._index_type = types[index_buffer.dtype]
            self.vertices = index_buffer.nbytes // index_buffer.dtype.itemsize

    def render(
        self,
        mode: Union[str, int] = "triangles",
        vertices: Optional[int] = None,
        first: int = 0,
        instances: int = 1,
    ) -> None:
        """Draws ``vertices`` vertices (default: all) from ``first`` as
        ``mode``: ``"points"``, ``"lines"``, ``"line_strip"``,
        ``"line_loop"``, ``"triangles"``, ``"triangle_strip"``,
        ``"triangle_fan"``, ``"quads"``, ``"quad_strip"`` or ``"polygon"``
        (these three: compatibility contexts only), or in 3.2+ contexts
        ``"lines_adjacency"``, ``"line_strip_adjacency"``,
        ``"triangles_adjacency"`` or ``"triangle_strip_adjacency"``.

        ``instances`` > 1 draws that many instances
        (glDrawArraysInstanced / glDrawElementsInstanced): ``gl_InstanceID``
        counts them and ``/i`` attributes advance once per instance."""
        gl_mode = _mode(mode)
        for n, v in (("first", first), ("instances", instances)) + ((("vertices", vertices),) if vertices is not None else ()):
            if not isinstance(v, (int, np.integer)) or isinstance(v, bool):
                raise TypeError(f"{n} must be an int, got {v!r}")
        if vertices is None and self.vertices is None:
            raise ValueError("no buffer of this vertex array is per vertex: say how many to draw with render(vertices=...)")
        count = (self.vertices or 0) - first if vertices is None else int(vertices)
        have = self.vertices
        if first < 0 or count < 0 or (self.index_buffer is None and have is not None and first + count > have):
            raise ValueError(f"cannot draw {count} vertices from {first}: the buffers hold {have}")
        if instances < 0:
            raise ValueError(f"instances must be >= 0, got {instances}")
        if self.instances is not None and instances > self.instances:
            raise ValueError(f"cannot draw {instances} instances: the per-instance buffers hold {self.instances}")
        raw = self.ctx._raw
        raw.use_program(self.program.glo)
        raw.reset_arrays()
        for name, f, buf, stride, offset, integer in self._bindings:
            if name.startswith("gl_"):
                if not raw.builtin_pointer(name, f.components, f.gl_type, stride, buf, offset):
                    raise KeyError(
                        f"{name!r} is not a built-in attribute (gl_Vertex, gl_Normal, gl_Color, "
                        "gl_SecondaryColor, gl_FogCoord, gl_MultiTexCoord0-7)"
                    )
            else:
                loc = self.program.attributes[name].location
                raw.attrib_pointer(loc, f.components, f.gl_type, f.normalized, stride, buf, offset, integer, f.divisor)
        _check_gl(raw, "specifying the vertex arrays")
        if self.index_buffer is not None:
            if first:
                raise ValueError("first is not supported with an index buffer")
            err = raw.draw_elements(gl_mode, count, self._index_type, self.index_buffer.glo, int(instances))
        else:
            err = raw.draw_arrays(gl_mode, int(first), count, int(instances))
        if err:
            raise Error(f"drawing failed: {err}")
        _check_gl(raw, "drawing")
        self.ctx._drawn = True

    def __repr__(self) -> str:
        names = [b[0] for b in self._bindings]
        inst = f", {self.instances} instances" if self.instances is not None else ""
        return f"<shaderbox.VertexArray {self.vertices} vertices{inst}: {names}>"


def _mode(mode: Union[str, int]) -> int:
    if isinstance(mode, str):
        m = _gl.MODES.get(mode.lower())
        if m is None:
            raise ValueError(f"mode {mode!r} is not one of: {', '.join(_gl.MODES)}")
        return m
    if isinstance(mode, (int, np.integer)) and 0 <= int(mode) <= 9:
        return int(mode)
    raise ValueError(f"mode {mode!r} is not a primitive mode")


# ---- textures ----------------------------------------------------------------


class Texture:
    """A 2D texture (made by :meth:`Context.texture`), bound to texture
    unit ``unit``; set a ``sampler2D`` uniform to it (or to ``unit``)."""

    def __init__(self, ctx: "Context", data: Any, unit: int, filter: str, wrap: str, mipmaps: bool):
        self.ctx = ctx
        if hasattr(data, "mode") and hasattr(data, "size") and not isinstance(data, np.ndarray):
            # A PIL image: convert palette and odd modes to RGBA.
            if data.mode not in ("L", "LA", "RGB", "RGBA"):
                data = data.convert("RGBA")
            data = np.asarray(data)
        a = np.asarray(data)
        if a.dtype == np.uint8:
            gl_type, float_tex = _gl.UNSIGNED_BYTE, False
        elif a.dtype == np.float32:
            gl_type, float_tex = _gl.FLOAT, True
        else:
            raise TypeError(
                f"texture data must be uint8 (0-255) or float32, got {a.dtype}; convert with .astype(np.uint8) or .astype(np.float32)"
            )
        if a.ndim == 2:
            a = a[:, :, None]
        if a.ndim != 3 or a.shape[2] not in (1, 2, 3, 4) or a.shape[0] < 1 or a.shape[1] < 1:
            raise ValueError(f"texture data is H x W or H x W x 1-4 (L, LA, RGB, RGBA), got shape {np.shape(data)}")
        h, w, c = a.shape
        if max(w, h) > _shaderbox.MAX_SIZE:
            raise ValueError(f"texture {w}x{h} is larger than {_shaderbox.MAX_SIZE} on a side")
        n_units = _shaderbox.MAX_TEXTURE_UNITS
        if not isinstance(unit, (int, np.integer)) or not 0 <= int(unit) < n_units:
            raise ValueError(f"texture unit {unit!r} is not 0-{n_units - 1}")
        fmt = {1: _gl.LUMINANCE, 2: _gl.LUMINANCE_ALPHA, 3: _gl.RGB, 4: _gl.RGBA}[c]
        internal = {1: _gl.LUMINANCE32F, 2: _gl.LUMINANCE_ALPHA32F, 3: _gl.RGB32F, 4: _gl.RGBA32F}[c] if float_tex else fmt
        filters = {"linear": _gl.LINEAR, "nearest": _gl.NEAREST}
        if filter not in filters:
            raise ValueError(f"filter {filter!r} is not 'linear' or 'nearest'")
        if wrap not in _gl.WRAPS:
            raise ValueError(f"wrap {wrap!r} is not one of: {', '.join(_gl.WRAPS)}")
        raw = ctx._raw
        self.unit = int(unit)
        self.width, self.height, self.components = w, h, c
        self.dtype = a.dtype
        self.glo = raw.gen_texture()
        u = self.unit
        raw.bind_texture(u, self.glo)
        raw.tex_image_2d(u, internal, w, h, fmt, gl_type, np.ascontiguousarray(a).tobytes())
        min_filter = filters[filter]
        if mipmaps:
            raw.generate_mipmap(u)
            min_filter = _gl.LINEAR_MIPMAP_LINEAR if filter == "linear" else _gl.NEAREST_MIPMAP_NEAREST
        raw.tex_parameteri(u, _gl.TEXTURE_MIN_FILTER, min_filter)
        raw.tex_parameteri(u, _gl.TEXTURE_MAG_FILTER, filters[filter])
        raw.tex_parameteri(u, _gl.TEXTURE_WRAP_S, _gl.WRAPS[wrap])
        raw.tex_parameteri(u, _gl.TEXTURE_WRAP_T, _gl.WRAPS[wrap])
        _check_gl(raw, "creating a texture")

    def use(self, unit: Optional[int] = None) -> None:
        """Binds the texture to ``unit`` (default: its own unit)."""
        if unit is not None:
            n_units = _shaderbox.MAX_TEXTURE_UNITS
            if not 0 <= int(unit) < n_units:
                raise ValueError(f"texture unit {unit!r} is not 0-{n_units - 1}")
            self.unit = int(unit)
        self.ctx._raw.bind_texture(self.unit, self.glo)

    def __repr__(self) -> str:
        return f"<shaderbox.Texture {self.glo}: {self.width}x{self.height}x{self.components} {self.dtype}, unit {self.unit}>"


# ---- fixed-function state ----------------------------------------------------


def _vec_property(pname: int, n: int, doc: str):
    def get(self) -> np.ndarray:
        return np.asarray(self._get(pname), dtype=np.float32)

    def set(self, value: ArrayLike) -> None:
        self._set(pname, _floats(value, n, doc.split(":")[0]))

    return property(get, set, doc=doc)


def _scalar_property(pname: int, doc: str):
    def get(self) -> float:
        v = self._get(pname)
        return float(v[0]) if v else 0.0

    def set(self, value: float) -> None:
        self._set(pname, _floats(value, 1, doc.split(":")[0]))

    return property(get, set, doc=doc)


class Light:
    """GL light ``index`` (``gl_LightSource[index]`` in shaders).

    Setting ``position`` or ``spot_direction`` transforms them by the
    current model-view matrix, as ``glLightfv`` does (set them with the
    model-view you mean, e.g. identity for eye-space lights); reading gives
    the eye-space values GL stores."""

    def __init__(self, ctx: "Context", index: int):
        self._ctx = ctx
        self.index = index

    def _get(self, pname: int) -> List[float]:
        return self._ctx._raw.get_lightfv(_gl.LIGHT0 + self.index, pname)

    def _set(self, pname: int, vals: List[float]) -> None:
        self._ctx._raw.lightfv(_gl.LIGHT0 + self.index, pname, vals)
        _check_gl(self._ctx._raw, f"setting light {self.index}")

    position = _vec_property(_gl.POSITION, 4, "position: (x, y, z, w); w = 0 for a directional light")
    ambient = _vec_property(_gl.AMBIENT, 4, "ambient: RGBA")
    diffuse = _vec_property(_gl.DIFFUSE, 4, "diffuse: RGBA")
    specular = _vec_property(_gl.SPECULAR, 4, "specular: RGBA")
    spot_direction = _vec_property(_gl.SPOT_DIRECTION, 3, "spot_direction: (x, y, z)")
    spot_exponent = _scalar_property(_gl.SPOT_EXPONENT, "spot_exponent: 0-128")
    spot_cutoff = _scalar_property(_gl.SPOT_CUTOFF, "spot_cutoff: 0-90 degrees, or 180 (no spot)")
    constant_attenuation = _scalar_property(_gl.CONSTANT_ATTENUATION, "constant_attenuation: >= 0")
    linear_attenuation = _scalar_property(_gl.LINEAR_ATTENUATION, "linear_attenuation: >= 0")
    quadratic_attenuation = _scalar_property(_gl.QUADRATIC_ATTENUATION, "quadratic_attenuation: >= 0")

    @property
    def enabled(self) -> bool:
        """glEnable(GL_LIGHTi) (what fixed-function lighting uses)."""
        return bool(self._ctx._raw.is_enabled(_gl.LIGHT0 + self.index))

    @enabled.setter
    def enabled(self, on: bool) -> None:
        (self._ctx._raw.enable if on else self._ctx._raw.disable)(_gl.LIGHT0 + self.index)

    def __repr__(self) -> str:
        return f"<shaderbox.Light {self.index}{' on' if self.enabled else ''}: position {self.position.tolist()}>"


class Material:
    """The front and back material (``gl_FrontMaterial`` /
    ``gl_BackMaterial``); setting changes both faces, reading gives the
    front one."""

    def __init__(self, ctx: "Context"):
        self._ctx = ctx

    def _get(self, pname: int) -> List[float]:
        return self._ctx._raw.get_materialfv(_gl.FRONT, pname)

    def _set(self, pname: int, vals: List[float]) -> None:
        self._ctx._raw.materialfv(_gl.FRONT_AND_BACK, pname, vals)
        _check_gl(self._ctx._raw, "setting the material")

    ambient = _vec_property(_gl.AMBIENT, 4, "ambient: RGBA")
    diffuse = _vec_property(_gl.DIFFUSE, 4, "diffuse: RGBA")
    specular = _vec_property(_gl.SPECULAR, 4, "specular: RGBA")
    emission = _vec_property(_gl.EMISSION, 4, "emission: RGBA")
    shininess = _scalar_property(_gl.SHININESS, "shininess: 0-128")

    def __repr__(self) -> str:
        return f"<shaderbox.Material shininess {self.shininess}>"


class Fog:
    """Fog state (``gl_Fog`` in shaders; ``enabled`` is glEnable(GL_FOG),
    which fixed-function fragment processing uses)."""

    def __init__(self, ctx: "Context"):
        self._ctx = ctx

    def _get(self, pname: int) -> List[float]:
        return self._ctx._raw.get_floatv(pname)

    def _set(self, pname: int, vals: List[float]) -> None:
        self._ctx._raw.fogfv(pname, vals)
        _check_gl(self._ctx._raw, "setting fog")

    color = _vec_property(_gl.FOG_COLOR, 4, "color: RGBA")
    density = _scalar_property(_gl.FOG_DENSITY, "density: >= 0 (exp and exp2)")
    start = _scalar_property(_gl.FOG_START, "start: eye distance where linear fog begins")
    end = _scalar_property(_gl.FOG_END, "end: eye distance where linear fog is full")

    @property
    def mode(self) -> str:
        """``"linear"``, ``"exp"`` or ``"exp2"``."""
        v = self._ctx._raw.get_integerv(_gl.FOG_MODE)
        code = v[0] if v else 0
        return next((k for k, c in _gl.FOG_MODES.items() if c == code), f"0x{code:04x}")

    @mode.setter
    def mode(self, mode: str) -> None:
        if mode not in _gl.FOG_MODES:
            raise ValueError(f"fog mode {mode!r} is not one of: {', '.join(_gl.FOG_MODES)}")
        self._ctx._raw.fogi(_gl.FOG_MODE, _gl.FOG_MODES[mode])

    @property
    def enabled(self) -> bool:
        return bool(self._ctx._raw.is_enabled(_gl.CAPS["fog"]))

    @enabled.setter
    def enabled(self, on: bool) -> None:
        (self._ctx._raw.enable if on else self._ctx._raw.disable)(_gl.CAPS["fog"])

    def __repr__(self) -> str:
        return f"<shaderbox.Fog {self.mode}{' on' if self.enabled else ''}>"


def _matrix_in(value: ArrayLike, what: str) -> List[float]:
    a = _numeric(value, what)
    if a.shape not in ((4, 4), (16,)):
        raise ValueError(f"{what} is a 4x4 matrix, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{what} must be finite")
    # m[row, col] -> GL's column-major order.
    return [float(x) for x in a.reshape(4, 4).T.reshape(-1)]


class Context:
    """An OpenGL context drawing into a ``width`` x ``height`` RGBA8
    framebuffer (with 24-bit depth and 8-bit stencil), on the CPU.

    ``version`` and ``profile`` choose the API: the default is OpenGL 2.1;
    ``version=(3, 3)`` gives 3.3, ``profile="core"`` (GLSL 1.30 and later
    only, no fixed-function state) or ``"compatibility"`` (everything).
    Make programs with :meth:`program`, vertex data with :meth:`buffer`
    and :meth:`vertex_array` (instanced attributes, integer attributes and
    uniform blocks in 3.3: :meth:`Buffer.bind_to_uniform_block`,
    :class:`UniformBlock`), textures with :meth:`texture`; set the
    fixed-function state shaders read through :attr:`lights`,
    :attr:`material`, :attr:`fog`, :attr:`modelview`, :attr:`projection`
    (compatibility contexts); :meth:`clear`, ``vao.render()``, then
    :meth:`read` / :meth:`image`. ``threads`` sets how many threads draws
    use (images do not depend on it; default: the machine's cores).
    """

    def __init__(
        self,
        width: int,
        height: int,
        *,
        threads: Optional[int] = None,
        version: Tuple[int, int] = (2, 1),
        profile: Optional[str] = None,
    ):
        for n, v in (("width", width), ("height", height)):
            if not isinstance(v, (int, np.integer)) or isinstance(v, bool):
                raise TypeError(f"{n} must be an int, got {type(v).__name__}")
        if (
            not isinstance(version, tuple)
            or len(version) != 2
            or not all(isinstance(x, int) and not isinstance(x, bool) for x in version)
        ):
            raise TypeError(f"version must be a (major, minor) tuple of ints, got {version!r}")
        if profile is None:
            profile = "core" if version >= (3, 2) else "compatibility"
        if profile not in ("core", "compatibility"):
            raise ValueError(f"profile must be 'core' or 'compatibility', got {profile!r}")
        self._raw = _shaderbox.RawContext(int(width), int(height), version[0], version[1], profile)
        if threads is not None:
            if not isinstance(threads, int) or threads < 0:
                raise ValueError(f"threads must be a non-negative int, got {threads!r}")
            self._raw.set_threads(threads)
        self._drawn = False
        major, minor, self._profile = self._raw.api()
        self._version = (int(major), int(minor))
        self._lights: Tuple[Light, ...] = tuple(Light(self, i) for i in range(_shaderbox.MAX_LIGHTS))
        self._material = Material(self)
        self._fog = Fog(self)

    @property
    def version(self) -> Tuple[int, int]:
        """The OpenGL version the context implements: (2, 1) or (3, 3)."""
        return self._version

    @property
    def profile(self) -> str:
        """``"core"`` or ``"compatibility"``."""
        return self._profile

    def _compatibility(self, what: str) -> None:
        if self._profile == "core":
            raise RuntimeError(
                f"{what} is fixed-function state, which the core profile removes: pass the values "
                "to your shaders as uniforms (or a uniform block), or create the context with "
                "profile='compatibility'"
            )

    @property
    def lights(self) -> Tuple[Light, ...]:
        """GL lights 0-7 (:class:`Light`); compatibility contexts only."""
        self._compatibility("lights")
        return self._lights

    @property
    def material(self) -> Material:
        """The material (:class:`Material`); compatibility contexts only."""
        self._compatibility("material")
        return self._material

    @property
    def fog(self) -> Fog:
        """The fog state (:class:`Fog`); compatibility contexts only."""
        self._compatibility("fog")
        return self._fog

    @property
    def width(self) -> int:
        return int(self._raw.width())

    @property
    def height(self) -> int:
        return int(self._raw.height())

    @property
    def size(self) -> Tuple[int, int]:
        return (self.width, self.height)

    # -- programs and data --

    def program(
        self,
        vertex_shader: Optional[str] = None,
        fragment_shader: Optional[str] = None,
        geometry_shader: Optional[str] = None,
    ) -> Program:
        """Compiles and links a program. A vertex or fragment stage left
        out is fixed-function; a ``geometry_shader`` (GLSL 1.50 and later,
        in a 3.2+ context) needs a ``vertex_shader``.

        Raises :class:`CompileError` or :class:`LinkError` with the
        compiler's diagnostics (line, column, message, and the rendered
        report with the source lines)."""
        if vertex_shader is None and fragment_shader is None:
            raise ValueError("a program needs a vertex_shader, a fragment_shader or both")
        stages = (
            ("vertex", vertex_shader, "vertex_shader"),
            ("geometry", geometry_shader, "geometry_shader"),
            ("fragment", fragment_shader, "fragment_shader"),
        )
        for _, s, n in stages:
            if s is not None and not isinstance(s, str):
                raise TypeError(f"{n} must be GLSL source text (str), got {type(s).__name__}")
        compatibility = self._profile != "core"
        reports = []
        for stage, src, label in stages:
            if src is not None:
                reports.append(_diagnostics(_shaderbox.compile_report(src, stage, None, label, compatibility)))
        if not all(r.ok for r in reports):
            merged = Diagnostics(
                [d for r in reports for d in r],
                text="".join(r.text for r in reports),
                info_log="".join(r.info_log for r in reports),
                ok=False,
            )
            raise CompileError(merged)
        link = _diagnostics(
            _shaderbox.link_report(vertex_shader, fragment_shader, compatibility, geometry_shader)
        )
        if not link.ok:
            raise LinkError(link)
        name, compiled, linked, log = self._raw.build_program(vertex_shader, fragment_shader, geometry_shader)
        if not (compiled and linked):
            # What only the context refuses (e.g. GLSL 1.10 in a core context).
            self._raw.delete_program(name)
            failed = Diagnostics([], text=log, info_log=log, ok=False)
            raise CompileError(failed) if not compiled else LinkError(failed)
        _check_gl(self._raw, "building the program")
        warnings = Diagnostics(
            [d for r in reports + [link] for d in r],
            text="".join(r.text for r in reports + [link]),
            info_log="".join(r.info_log for r in reports + [link]),
            ok=True,
        )
        return Program(self, name, warnings)

    def buffer(self, data: Any = None, *, reserve: int = 0) -> Buffer:
        """A buffer object holding ``data`` (a numeric numpy array, anything
        ``np.asarray`` takes, or bytes), or ``reserve`` zero bytes (fill
        them with :meth:`Buffer.write`)."""
        if data is None:
            if not isinstance(reserve, (int, np.integer)) or isinstance(reserve, bool) or reserve < 1:
                raise ValueError(f"buffer: give data, or reserve a positive number of bytes (got reserve={reserve!r})")
            return Buffer(self, bytes(int(reserve)))
        if reserve:
            raise ValueError("buffer: give data or reserve, not both")
        return Buffer(self, data)

    def vertex_array(
        self,
        program: Program,
        content: Sequence[Tuple[Any, ...]],
        index_buffer: Any = None,
    ) -> VertexArray:
        """Binds buffers to ``program``'s attributes.

        ``content`` lists ``(buffer, format, name, ...)``: a :class:`Buffer`
        or numpy array, a format like ``"3f"`` or ``"3f 4f"`` (interleaved,
        see :func:`parse_format`; ``"3f 4f/i"`` per instance), and one
        attribute name per field, either the program's own attributes or
        built-in ones (``"gl_Vertex"``, ``"gl_Normal"``, ``"gl_Color"``,
        ``"gl_MultiTexCoord0"``...; compatibility contexts only).
        ``int``/``ivecN``/``uint``/``uvecN`` attributes take integer
        formats and get the values unconverted (glVertexAttribIPointer).
        ``index_buffer`` (integers) makes :meth:`VertexArray.render` draw
        indexed."""
        return VertexArray(self, program, content, index_buffer)

    def texture(
        self,
        data: Any,
        *,
        unit: int = 0,
        filter: str = "linear",
        wrap: str = "repeat",
        mipmaps: bool = False,
    ) -> Texture:
        """A 2D texture from an ``H x W [x 1-4]`` uint8 or float32 array (or a
        PIL image), bound to texture unit ``unit``. Row 0 of the array is
        t = 0 (GL's convention: pass ``np.flipud(a)`` for an image stored
        top row first if t = 0 should be its bottom)."""
        return Texture(self, data, unit, filter, wrap, mipmaps)

    # -- state --

    def enable(self, *caps: str) -> None:
        """glEnable by name: ``"depth_test"``, ``"blend"``, ``"cull_face"``,
        ``"lighting"``, ``"fog"``, ``"texture_2d"``, ``"alpha_test"``,
        ``"normalize"``, ``"point_sprite"``, ``"vertex_program_point_size"``..."""
        for c in caps:
            self._raw.enable(_cap(c))

    def disable(self, *caps: str) -> None:
        """glDisable by name (see :meth:`enable`)."""
        for c in caps:
            self._raw.disable(_cap(c))

    def is_enabled(self, cap: str) -> bool:
        return bool(self._raw.is_enabled(_cap(cap)))

    @property
    def depth_test(self) -> bool:
        """glEnable(GL_DEPTH_TEST)."""
        return self.is_enabled("depth_test")

    @depth_test.setter
    def depth_test(self, on: bool) -> None:
        (self.enable if on else self.disable)("depth_test")

    def depth_func(self, func: str) -> None:
        """glDepthFunc: ``"<"``/``"less"``, ``"<="``, ``">"``, ``"always"``..."""
        if func not in _gl.DEPTH_FUNCS:
            raise ValueError(f"depth function {func!r} is not one of: {', '.join(_gl.DEPTH_FUNCS)}")
        self._raw.depth_func(_gl.DEPTH_FUNCS[func])

    def blend_func(self, src: str = "src_alpha", dst: str = "one_minus_src_alpha") -> None:
        """glBlendFunc by names (enable blending with ``enable("blend")``)."""
        for f in (src, dst):
            if f not in _gl.BLEND_FACTORS:
                raise ValueError(f"blend factor {f!r} is not one of: {', '.join(_gl.BLEND_FACTORS)}")
        self._raw.blend_func(_gl.BLEND_FACTORS[src], _gl.BLEND_FACTORS[dst])

    def cull_face(self, face: str = "back") -> None:
        """glCullFace (enable culling with ``enable("cull_face")``)."""
        if face not in _gl.CULL_FACES:
            raise ValueError(f"face {face!r} is not one of: {', '.join(_gl.CULL_FACES)}")
        self._raw.cull_face(_gl.CULL_FACES[face])

    def point_size(self, size: float) -> None:
        """glPointSize."""
        self._raw.point_size(float(size))
        _check_gl(self._raw, "setting the point size")

    @property
    def viewport(self) -> Tuple[int, int, int, int]:
        """(x, y, width, height); the whole framebuffer by default."""
        v = self._raw.get_integerv(_gl.VIEWPORT)
        return (v[0], v[1], v[2], v[3])

    @viewport.setter
    def viewport(self, v: Sequence[int]) -> None:
        x, y, w, h = (int(t) for t in v)
        self._raw.viewport(x, y, w, h)
        _check_gl(self._raw, "setting the viewport")

    @property
    def light_model_ambient(self) -> np.ndarray:
        """``gl_LightModel.ambient`` (RGBA)."""
        self._compatibility("light model ambient")
        return np.asarray(self._raw.get_floatv(_gl.LIGHT_MODEL_AMBIENT), dtype=np.float32)

    @light_model_ambient.setter
    def light_model_ambient(self, rgba: ArrayLike) -> None:
        self._compatibility("light model ambient")
        self._raw.light_modelfv(_gl.LIGHT_MODEL_AMBIENT, _floats(rgba, 4, "light_model_ambient"))

    @property
    def modelview(self) -> np.ndarray:
        """The model-view matrix, 4x4 as ``m[row, col]`` (``gl_ModelViewMatrix``)."""
        self._compatibility("modelview")
        return _matrix_out(self._raw.get_floatv(_gl.MODELVIEW_MATRIX))

    @modelview.setter
    def modelview(self, m: ArrayLike) -> None:
        self._load(_gl.MODELVIEW, _matrix_in(m, "modelview"))

    @property
    def projection(self) -> np.ndarray:
        """The projection matrix, 4x4 as ``m[row, col]`` (``gl_ProjectionMatrix``)."""
        self._compatibility("projection")
        return _matrix_out(self._raw.get_floatv(_gl.PROJECTION_MATRIX))

    @projection.setter
    def projection(self, m: ArrayLike) -> None:
        self._load(_gl.PROJECTION, _matrix_in(m, "projection"))

    def _load(self, mode: int, m: List[float]) -> None:
        self._compatibility("the modelview and projection matrices")
        self._raw.matrix_mode(mode)
        self._raw.load_matrixf(m)
        self._raw.matrix_mode(_gl.MODELVIEW)
        _check_gl(self._raw, "loading a matrix")

    def ortho(self, left: float, right: float, bottom: float, top: float, near: float = -1.0, far: float = 1.0) -> None:
        """Sets the projection to glOrtho(left, right, bottom, top, near, far)."""
        l, r, b, t, n, f = (float(v) for v in (left, right, bottom, top, near, far))
        if l == r or b == t or n == f:
            raise ValueError("ortho: left/right, bottom/top and near/far must differ")
        m = np.array(
            [
                [2 / (r - l), 0, 0, -(r + l) / (r - l)],
                [0, 2 / (t - b), 0, -(t + b) / (t - b)],
                [0, 0, -2 / (f - n), -(f + n) / (f - n)],
                [0, 0, 0, 1],
            ]
        )
        self.projection = m

    def perspective(self, fovy: float, aspect: Optional[float] = None, near: float = 0.1, far: float = 100.0) -> None:
        """Sets the projection to gluPerspective(fovy degrees, aspect, near,
        far); ``aspect`` defaults to width / height."""
        a = self.width / self.height if aspect is None else float(aspect)
        if not (0 < fovy < 180) or not (0 < near < far) or a <= 0:
            raise ValueError("perspective: need 0 < fovy < 180, 0 < near < far and aspect > 0")
        f = 1.0 / np.tan(np.radians(fovy) / 2)
        m = np.array(
            [
                [f / a, 0, 0, 0],
                [0, f, 0, 0],
                [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
                [0, 0, -1, 0],
            ]
        )
        self.projection = m

    def look_at(self, eye: ArrayLike, target: ArrayLike = (0, 0, 0), up: ArrayLike = (0, 1, 0)) -> None:
        """Sets the model-view to gluLookAt(eye, target, up)."""
        e = np.asarray(_floats(eye, 3, "eye"), dtype=np.float64)
        c = np.asarray(_floats(target, 3, "target"), dtype=np.float64)
        u = np.asarray(_floats(up, 3, "up"), dtype=np.float64)
        fwd = c - e
        if np.linalg.norm(fwd) == 0:
            raise ValueError("look_at: eye and target are the same point")
        fwd /= np.linalg.norm(fwd)
        s = np.cross(fwd, u)
        if np.linalg.norm(s) == 0:
            raise ValueError("look_at: up is parallel to the view direction")
        s /= np.linalg.norm(s)
        u2 = np.cross(s, fwd)
        m = np.identity(4)
        m[0, :3], m[1, :3], m[2, :3] = s, u2, -fwd
        m[:3, 3] = -m[:3, :3] @ e
        self.modelview = m

    # -- drawing and reading --

    def clear(self, color: ArrayLike = (0.0, 0.0, 0.0, 1.0), depth: float = 1.0) -> None:
        """Clears the color buffer to ``color`` (RGB or RGBA, 0-1) and the
        depth buffer to ``depth``."""
        c = _numeric(color, "clear color").reshape(-1)
        if c.size == 3:
            c = np.append(c, 1.0)
        rgba = _floats(c, 4, "clear color")
        self._raw.clear_color(*rgba)
        self._raw.clear_depth(float(depth))
        self._raw.clear(_gl.COLOR_BUFFER_BIT | _gl.DEPTH_BUFFER_BIT | _gl.STENCIL_BUFFER_BIT)
        _check_gl(self._raw, "clearing")
        self._drawn = True

    def _check_drawn(self) -> None:
        if not self._drawn:
            raise Error(
                "nothing has been drawn into this context yet: call ctx.clear() and/or render a vertex array before reading"
            )

    def debug_pixel(self, x: int, y: int, *, draw: Optional[int] = None, vertex: Optional[int] = None) -> "PixelDebug":
        """Traces window pixel (``x``, ``y``) (bottom-left origin) in the
        draws made inside the ``with`` block::

            with ctx.debug_pixel(10, 20) as dbg:
                vao.render()
            print(dbg.text)                      # source lines beside values
            dbg.data["draws"][0]["fragments"]    # the same, structured

        Every fragment that reached the pixel, in order: its primitive and
        vertices, interpolated inputs, each statement its shader ran with
        the values stored, ``discard``, outputs, and the depth/stencil/blend
        decisions. ``draw`` keeps only the n-th draw of the block (0 is the
        first); ``vertex`` also traces the vertex shader of that vertex.
        """
        for n, v in (("x", x), ("y", y)):
            if not isinstance(v, (int, np.integer)) or isinstance(v, bool) or v < 0:
                raise ValueError(f"{n} must be a non-negative int, got {v!r}")
        for n, v in (("draw", draw), ("vertex", vertex)):
            if v is not None and (not isinstance(v, (int, np.integer)) or isinstance(v, bool) or v < 0):
                raise ValueError(f"{n} must be a non-negative int or None, got {v!r}")
        return PixelDebug(self, int(x), int(y), draw, vertex)

    def read(self) -> np.ndarray:
        """The color buffer as an ``H x W x 4`` ``uint8`` array, top row first."""
        self._check_drawn()
        w, h = self.width, self.height
        data = self._raw.read_pixels(0, 0, w, h)
        _check_gl(self._raw, "reading pixels")
        return np.frombuffer(data, dtype=np.uint8).reshape(h, w, 4)[::-1].copy()

    def read_depth(self) -> np.ndarray:
        """The depth buffer as an ``H x W`` ``float32`` array (window depth
        0-1), top row first."""
        self._check_drawn()
        w, h = self.width, self.height
        data = self._raw.read_depth(0, 0, w, h)
        _check_gl(self._raw, "reading depth")
        return np.frombuffer(data, dtype="<f4").reshape(h, w)[::-1].astype(np.float32)

    def image(self, alpha: bool = False) -> Image:
        """The color buffer as an :class:`Image` (shown by notebooks, saved
        with ``.save("out.png")``); ``alpha=True`` keeps the alpha channel
        in the PNG."""
        return Image(self.read(), has_alpha=alpha)

    def draw_spheres(self, centers: ArrayLike, radii: ArrayLike = 1.0, colors: ArrayLike = (0.8, 0.8, 0.8), **kw: Any) -> Program:
        """Draws spheres with the seed's ray-cast impostor shaders; see
        :func:`shaderbox.spheres.draw_spheres`."""
        if self._profile == "core":
            raise RuntimeError(
                "draw_spheres runs the seed's GLSL 1.10 shaders with the fixed-function lights, material and "
                "matrices, which the core profile removes: create the context with profile='compatibility' "
                "(or draw impostors with your own #version 330 program, as the example notebook does)"
            )
        from .spheres import draw_spheres

        return draw_spheres(self, centers, radii, colors, **kw)

    def __repr__(self) -> str:
        return f"<shaderbox.Context {self.width}x{self.height}>"


def _cap(name: str) -> int:
    if name not in _gl.CAPS:
        raise ValueError(f"capability {name!r} is not one of: {', '.join(_gl.CAPS)}")
    return _gl.CAPS[name]


def _matrix_out(v: Iterable[float]) -> np.ndarray:
    return np.asarray(list(v), dtype=np.float32).reshape(4, 4).T.copy()


class PixelDebug:
    """The trace of one pixel over the draws of a ``with`` block
    (:meth:`Context.debug_pixel`): :attr:`text` is the readable report,
    :attr:`data` the same as a dict (the JSON of ``shaderbox debug``)."""

    def __init__(self, ctx: Context, x: int, y: int, draw: Optional[int], vertex: Optional[int]):
        self._ctx = ctx
        self.pixel = (x, y)
        self._args = (x, y, draw, vertex)
        self.text = ""
        self.data: Dict[str, Any] = {}

    def __enter__(self) -> "PixelDebug":
        self._ctx._raw.debug_begin(*self._args)
        return self

    def __exit__(self, *exc: Any) -> None:
        import json

        text, js = self._ctx._raw.debug_end()
        self.text = text
        self.data = json.loads(js)
        self.data["pixel"] = list(self.pixel)

    @property
    def fragments(self) -> List[Dict[str, Any]]:
        """Every fragment of every traced draw, in order."""
        return [f for d in self.data.get("draws", []) for f in d.get("fragments", [])]

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        return f"<PixelDebug {self.pixel}: {len(self.fragments)} fragment(s)>"
