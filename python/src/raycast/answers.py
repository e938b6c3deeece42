"""Answer arrays: numpy arrays that also answer the tensor methods Open3D scripts call on
query results (`.numpy()`, `.cpu()`, `.to(dtype)`, `.item()`), so such code runs unchanged."""
import numpy as np

# Open3D's dtype names (str(open3d.core.float32) == "Float32") as numpy's.
_DTYPE_NAMES = {"bool": np.bool_, "float32": np.float32, "float64": np.float64,
                "int8": np.int8, "int16": np.int16, "int32": np.int32, "int64": np.int64,
                "uint8": np.uint8, "uint16": np.uint16, "uint32": np.uint32,
                "uint64": np.uint64}


def _numpy_dtype(dtype):
    """A numpy dtype from a numpy dtype, a Python type, a name, or an Open3D Dtype."""
    if isinstance(dtype, (np.dtype, type)):
        return np.dtype(dtype)
    name = str(dtype).lower()
    if name in _DTYPE_NAMES:
        return np.dtype(_DTYPE_NAMES[name])
    try:
        return np.dtype(name)
    except TypeError:
        raise TypeError(f"to(): expected a dtype (numpy, Open3D or a name such as 'float32'), "
                        f"got {dtype!r}") from None


def _is_cpu(device):
    return str(device).lower().split(":")[0] == "cpu"


class Tensor(np.ndarray):
    """A numpy array (a view, no copy) with Open3D's tensor methods. Indexing with an integer
    gives a 0-d Tensor, as Open3D does, so `ans["t_hit"][0].item()` and `.cpu()` both work."""

    def numpy(self):
        """The same data as a plain numpy array (no copy)."""
        return self.view(np.ndarray)

    def cpu(self):
        """Itself: raycast's answers live in host memory."""
        return self

    def contiguous(self):
        """A C-contiguous Tensor (itself when it already is one)."""
        return np.ascontiguousarray(self).view(Tensor)

    def clone(self):
        """A copy."""
        return self.copy()

    def to(self, dtype_or_device, copy=False):
        """Converted to a dtype (numpy's or Open3D's), or itself for a CPU device."""
        if _is_cpu(dtype_or_device):
            return self.copy() if copy else self
        target = _numpy_dtype(dtype_or_device)
        if target == self.dtype and not copy:
            return self
        return self.astype(target)

    def __getitem__(self, key):
        item = super().__getitem__(key)
        if isinstance(item, np.ndarray):
            return item
        return np.asarray(item).view(Tensor)  # a numpy scalar as a 0-d Tensor


def as_answer(array, dtype=None):
    """`array` as a Tensor, converted to `dtype` when given (one pass, no copy otherwise)."""
    a = np.asarray(array)
    if dtype is not None and a.dtype != dtype:
        a = a.astype(dtype)
    return a.view(Tensor)


def answer_dict(arrays, dtypes):
    """Each array of the dict as a Tensor converted by dtypes[key] (None keeps it)."""
    return {key: as_answer(value, dtypes.get(key)) for key, value in arrays.items()}
