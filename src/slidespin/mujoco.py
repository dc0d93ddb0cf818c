"""slidespin's exact patch friction inside MuJoCo (MODEL §16).

``slidespin.mujoco.attach(model, data, body_name, body, friction)``, after which a plain
``mujoco.mj_step(model, data)`` steps with slidespin's friction on that body, and ``detach``.
The implementation lives in :mod:`slidespin.engines.mujoco` (the engines layer); this module
is the name users import. Needs the extra: ``pip install "slidespin[mujoco]"``.
"""

from slidespin.engines.mujoco import Coupling, attach, attached, detach, set_twist
from slidespin.engines.scenes import mujoco_xml

__all__ = ["Coupling", "attach", "attached", "detach", "mujoco_xml", "set_twist"]
