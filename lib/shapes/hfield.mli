(** The height field (POV-Ray 3.7's HField, shape/hfield.cpp). In its own space the field's
    vertex (x, z), for x < [width] and z < [height], stands at the height of its image pixel
    (0 … 65535; z = 0 is the image's bottom row); each cell between four vertices is two triangles,
    (x, z)–(x+1, z)–(x, z+1) and (x+1, z+1)–(x, z+1)–(x+1, z). Parse_HField's scaling maps the field
    to the unit cube, and every modifier composes into that transform. Rays are walked through a
    grid of blocks (about √n per axis, each with its height range) and, within a block, cell by
    cell (POV-Ray's block_traversal and dda_traversal). *)

type f32s = (float, Bigarray.float32_elt, Bigarray.c_layout) Bigarray.Array1.t

type field = private {
  width : int;  (** vertices along x: the image's width *)
  height : int;  (** vertices along z: the image's height *)
  map : f32s;  (** the heights, at [z·width + x] (integers, exact in single precision) *)
  min_y : int;  (** the lowest height *)
  max_y : int;  (** the highest height *)
  water : float;  (** 65536 · water_level, as parsed (0 without) *)
  lo_y : float;  (** the box's bottom: max(min_y, water) − 0.001 (HFIELD_OFFSET) *)
  hi_y : float;  (** the box's top: max_y + 0.001 *)
  smooth : bool;
      (** [smooth]: normals blended from the vertex normals, which each worker makes as it needs
          them ({!Scratch.vertex_normals}) *)
  hierarchy : bool;  (** the block grid is built (POV-Ray's default); off: one block *)
  nbx : int;  (** blocks along x *)
  nbz : int;  (** blocks along z *)
  wbx : int;  (** a block's width in cells along x *)
  wbz : int;  (** … and along z *)
  blocks : int array;  (** 4 per block, row by row in z: first and last cell in x, first and last in z *)
  block_y : float array;  (** 2 per block: its height range (water included), widened by 0.001 *)
  sealed : bool;  (** the object's modifiers are read: [hierarchy] no longer rebuilds the blocks *)
}
(** The field as Compute_HField leaves it, but for the vertex normals; shared by every copy of
    the object, and never written once made. *)

type t = { field : field; tr : Transform.t  (** field space to world *) }

val make : width:int -> height:int -> heights:int array -> water:float -> smooth:bool -> field
(** [make ~width ~height ~heights ~water ~smooth] is Compute_HField: the box's heights and the
    blocks with the hierarchy on (build_hfield_blocks). [water] is 65536 · water_level. The
    vertex normals of a [smooth] field (smooth_height_field) are made by the workers as their
    rays need them.
    @raise Failure when a smooth field is one vertex wide or deep (it has no vertex normals). *)

val with_hierarchy : field -> bool -> field
(** [with_hierarchy f on] is [f] with its blocks built again with the hierarchy [on] or off, while
    its object's modifiers are being read; a sealed field is returned as it is. *)

val seal : field -> field
(** [seal f] is [f] once its object's modifiers are read (Compute_HField runs after them). *)

val scaling : field -> Transform.t
(** [scaling f] is Parse_HField's transform: scale by <1/(width − 1), 1/65536, 1/(height − 1)>. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w t o d lo] is HField::All_Intersections for a top-level height field, then the nearest
    of its hits at least [lo] (the last of equal depths), its part left in [w.part]; or infinity.
    The ray is brought into field space without renormalising, met with the field's box from
    1e-6 (HFIELD_TOLERANCE) on, and walked; the walk stops at the first cell with a hit at a depth
    within the box, whatever [lo] then keeps. Counted as POV-Ray counts its "Height Field" rows. *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w t id o d lo n] pushes every hit at least [lo], as hits of the member [id]: a height
    field in a CSG walks every cell (IS_CHILD_OBJECT); it is the new count. *)

val normal : Scratch.t -> t -> int -> Vec.t -> Vec.t
(** [normal w t part p] is the unit world normal: of a flat field, the normal of the triangle hit
    ([part] = 2·(z·width + x) + triangle), by the inverse transpose and normalised as
    intersect_pixel stores it; of a smooth one, HField::Normal at [p]: the four vertex normals of
    the cell (as POV-Ray stores them: shorts, 32767·N truncated, kept by the worker [w] once
    made), each by the inverse transpose and normalised, blended bilinearly, normalised. *)

val inside : t -> Vec.t -> bool
(** [inside t p] is HField::Inside of the world point [p], before the inverted flag: within the
    field's x and z extent (the far sides excluded), below its box's top, and below the water or
    the surface of the triangle above the point (heights below the water raised to it). *)

val bounds : t -> float array
(** [bounds t] is the box of the field's box mapped by its transform. *)

val pov_box : t -> float array
(** [pov_box t] is HField::Compute_BBox: the field's box in single precision, then Recompute_BBox
    through the transform. *)

val traits : Traits.t
(** [traits] is its kind's traits: [Traits.default]. *)
