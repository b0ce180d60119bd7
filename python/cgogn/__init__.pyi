# SPDX-License-Identifier: MIT
from typing import Any, Tuple, Union

from ._cgogn import CMap2 as CMap2
from ._cgogn import CMap3 as CMap3
from ._cgogn import Error as Error
from ._cgogn import GMap2 as GMap2
from ._cgogn import GMap3 as GMap3
from ._cgogn import IOError as IOError
from ._cgogn import RenderError as RenderError
from ._cgogn import load as load
from ._cgogn import nb_workers as nb_workers
from ._cgogn import set_nb_workers as set_nb_workers

def laplacian(m: CMap2, kind: str = "cotan") -> Any: ...
def to_meshio(m: Union[CMap2, CMap3]) -> Any: ...
def from_meshio(mesh: Any) -> Union[CMap2, CMap3]: ...
def to_pyvista(m: Union[CMap2, CMap3]) -> Any: ...
def to_trimesh(m: Union[CMap2, CMap3]) -> Any: ...
