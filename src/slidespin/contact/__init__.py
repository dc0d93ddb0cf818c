"""Contact: what touches the plane, independent of time (MODEL §1–4, §9–10).

Every patch shape (ellipse, disk, polygon, rectangle, ring, pads, blade) as one family, the
pressure laws and user pressure maps, the friction tensor and its speed-dependent laws
(MODEL §14), the body resting on its patch (the
patch with its mass centre, mass and inertia: what the wrench, the static set and the limit
surface need), the tilted plane it rests on, the compiled wrench kernels behind one compiled
entry that reads the patch's array form, the public wrench (:func:`~slidespin.friction_wrench`), the
static-friction set, the limit surface, the outline a pusher touches and the motion cone of a
push (MODEL §13).

May import: ``slidespin._validate``, ``slidespin._jit``, ``slidespin._io`` and itself only.
"""
