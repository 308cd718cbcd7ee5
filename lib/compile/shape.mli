(** Every operation on a shape, dispatched by one direct [match] to the shape's own module
    (lib/shapes/). The tracer and the compile step reach shapes through it (besides the scene
    search's flat-array sphere test, [Sphere.depth_at], and [Csg.is_csg]). A new shape is a module
    of its own, one case in each operation here and one line in [traits]; what a kind of shape is
    (costly, its box test free, …) is asked of its traits. *)

val compile : iso_slot:int -> Scene.shape -> Compiled.shape option
(** [compile ~iso_slot s] is the primitive [s] ready to trace; None for a CSG (the compile step
    builds it, numbering its members) and for a shape POV-Ray never hits (a triangle without area,
    a standalone smooth triangle whose vertex normals straddle its face, a cylinder, disc or
    letter whose transform has no inverse). An isosurface is numbered [iso_slot] among the
    scene's ({!Isosurface.compiled.slot}); other shapes ignore it. *)

val traits : Compiled.shape -> Traits.t
(** [traits shape] is the traits of [shape]'s kind, as its module writes them (a sphere's, an
    ellipsoid's, a moved box's, …; a CSG's are [Shape_kind.csg]): the one place that lists every
    compiled shape for what a kind of shape is. *)

val depth : Scratch.t -> Compiled.shape -> Vec.t -> Vec.t -> float -> float
(** [depth w shape o d lo] is the nearest depth along the unit direction [d] at which the ray from
    [o] meets [shape] within the shape's own limits and at least [lo] (§2, §14.5), or infinity; the
    part hit (mesh face, box side, cylinder part, letter part) is left in [w.part], the member hit
    by a CSG in [w.leaf]; a julia fractal, a bicubic patch or a parametric surface (or a CSG whose
    member hit is one) leaves its report of the crossing in [w.crossing] and sets [w.reported]. *)

val all_hits : Scratch.t -> Compiled.member -> Vec.t -> Vec.t -> float -> int -> int
(** [all_hits w m o d lo n] appends to [w.hits], after its first [n], every crossing at depth ≥
    [lo] of the primitive or CSG [m] (a member's geometry, or an object's as {!Compile.member}
    gives it) that POV-Ray's All_Intersections keeps (§16.2), in the order it pushes them; it is
    the new count. *)

val hit_object : Scratch.t -> Compiled.obj -> int
(** [hit_object w ob] is the id of the object a [depth] test of [ob] found: [ob] itself, or for a
    CSG the member primitive hit. *)

val normal : Scratch.t -> Compiled.obj -> int -> Vec.t -> Vec.t
(** [normal w obj part p] is the unit normal of [obj] at its surface point [p] ([part] as [depth]
    left it), before it is turned toward the ray (§3.1, §14.6); a smooth height field's vertex
    normals are the worker [w]'s. *)

val geometric_normal : Scratch.t -> Compiled.obj -> int -> Vec.t -> Vec.t
(** [geometric_normal w obj part p] is the flat normal of the surface at [p]: a smooth triangle's or
    face's own plane, else [normal]. The robust mode lifts secondary rays along it. *)

val uv : Compiled.obj -> int -> Crossing.t -> Vec.t -> Vec.t
(** [uv obj part c p] is the UV coordinates (u, v, 0) of [obj] at its world surface point [p]
    ([part] as [depth] left it: the box side, the mesh face), as POV-Ray 3.7's UVCoord methods
    compute them, in the shape's own space: spheres (in the frame of every modifier they got),
    boxes, tori, lathes, sors, ovus and meshes (their uv_vectors blended), bicubic patches and
    parametric surfaces (the coordinates their crossing reported, [c]); every other shape has
    POV-Ray's default, the world point's x and y. *)

val hit_normal : Scratch.t -> Compiled.obj -> int -> Crossing.t -> Vec.t -> Vec.t
(** [hit_normal w obj part c p] is the normal at the hit at [p] whose crossing reported [c]:
    [normal w obj part p], but for the shapes whose normal comes with the crossing: a julia
    fractal's and a bicubic patch's is the one reported, a parametric surface's is computed at
    the (u, v) reported (Parametric.hit_normal). *)

val hit_point : Scratch.t -> Compiled.obj -> Crossing.t -> Vec.t -> float -> Vec.t -> Vec.t
(** [hit_point w obj c o depth d] is the point POV-Ray shades where the ray from [o] along [d]
    hits the primitive [obj] at [depth], its crossing having reported [c]: [o + depth·d], except
    for a poly, whose point comes back from its own space ([Poly.hit_point]), and a julia
    fractal, whose march found its own point (the point of [c]). *)

val refine : Compiled.obj -> Vec.t -> Vec.t
(** [refine obj p] is the hit point [p] put back onto the surface where the shape allows it
    (spheres and ellipsoids), else [p]: the robust mode's hit points. *)

val inside : float array -> Compiled.shape -> Vec.t -> bool
(** [inside stack shape p] is POV-Ray's Inside test of [shape] (§2.2, §2.3, §2.6, §15.1–§15.5,
    §15.9, §16.3); [stack] is traversal room for meshes (512 floats). *)

val inside_member : float array -> Compiled.member -> Vec.t -> bool
(** [inside_member stack m p] is the Inside test of the CSG member [m]: a primitive's negated when
    it is inverted; an inverted (morphed) CSG's and an inverted quadric's (its coefficients negated)
    as they are (§16.3). *)

val bounds : Compiled.shape -> float array option
(** [bounds shape] is the box of a bounded shape (min x, y, z, max x, y, z); None for an unbounded
    one. A transformed shape's box is its object-space box with the corners mapped (§15.8). *)

val magnitude : Compiled.shape -> float
(** [magnitude shape] is the largest coordinate magnitude the shape's intersection works with: its
    box's; for an unbounded shape, a plane's point nearest the origin, a quadric's scale from its
    coefficients, a CSG's largest member's; the robust mode's scale of rounding errors. *)

val pov_box : Compiled.shape -> float array
(** [pov_box shape] is POV-Ray's box of the shape as it stores it ([Pov_box]); [[||]] when unbounded. *)

val costly : Compiled.shape -> bool
(** [costly shape] is true for the shapes costlier to test than their own box (its traits'
    [costly]: every shape but spheres, planes, triangles, meshes, boxes in world space and CSGs):
    the scene's search tries the box first. *)

val as_sphere : Compiled.shape -> Sphere.t option
(** [as_sphere shape] is the sphere that [shape] is, which the scene's search tests straight from
    a flat array. *)

val face_texture : Compiled.obj -> int -> int
(** [face_texture obj part] is the index of the texture of the mesh face [part] in [obj.face_surfs],
    or −1 when the object's own surface is shaded there. *)

val cached_depth : Scratch.t -> Compiled.shape -> Vec.t -> Vec.t -> float -> float -> float
(** [cached_depth w s o d lo hi] is Trace::FindIntersection of the one object [s] (the shadow cache's
    test) up to the depth [hi]: [depth], but a sphere, box, plane or triangle under clipped_by or
    bounded_by skips the wrapper's box test, as POV-Ray's Intersect_BBox of those shapes always
    passes, and an isosurface is tried only when the ray meets its box before [hi]. *)

val box_test_free : Compiled.shape -> bool
(** [box_test_free s] holds for a shape whose traits say its box test is free (a sphere, ellipsoid,
    box, plane, triangle or poly), and such a shape under clipped_by or bounded_by: POV-Ray's
    Intersect_BBox of those always passes. *)
