(** Bounding-volume hierarchies: binned surface-area heuristic, stored flat in single precision
    outside the OCaml heap (no allocation while traversing). Used over the scene's bounded objects
    and inside each mesh. *)

type f32s = (float, Bigarray.float32_elt, Bigarray.c_layout) Bigarray.Array1.t
type i32s = (int32, Bigarray.int32_elt, Bigarray.c_layout) Bigarray.Array1.t

type t = private {
  boxes : f32s;  (** 6 values per node: min x, y, z then max x, y, z *)
  links : i32s;
      (** 3 per node. Leaf: first index into [order], count, −1. Inner: left child, right child,
          split axis (0, 1, 2). Node 0 is the root. The arrays may be longer than [nodes] needs. *)
  order : i32s;  (** primitive indices in leaf order *)
  nodes : int;  (** number of nodes; 0 for an empty hierarchy *)
}

val create_boxes : int -> f32s
(** [create_boxes n] is room for [n] primitive boxes, filled with [set_box]. *)

val set_box : f32s -> int -> float -> float -> float -> float -> float -> float -> unit
(** [set_box boxes i x0 y0 z0 x1 y1 z1] stores primitive [i]'s box, widened by a relative 1e-9 and
    rounded outwards to single precision. *)

val build : f32s -> t
(** [build boxes] builds a hierarchy over the primitives whose boxes were stored with [set_box].
    It reorders [boxes] in place (into leaf order), so they are of no further use. *)

val entry : t -> int -> float -> float -> float -> float -> float -> float -> float -> float -> float
(** [entry bvh k ox oy oz idx idy idz tmin tmax] is the distance at which the ray from (ox,oy,oz)
    with reciprocal direction (idx,idy,idz) enters node [k]'s box, if it meets the box between
    [tmin] and [tmax]; infinity otherwise. A zero direction component must be given a huge finite
    reciprocal, not infinity. *)

val recip : float -> float
(** [recip x] is 1/x, or a huge finite number for 0, as [entry] needs. *)

val walk : t -> float array -> float -> float -> float -> float -> float -> float -> float -> (int -> float) -> unit
(** [walk bvh stack ox oy oz dx dy dz limit visit] calls [visit i] for every primitive [i] in a leaf
    whose box the ray from (ox,oy,oz) along (dx,dy,dz) meets before the current limit, nearer boxes
    first; [visit] returns the new limit ([limit] at the start). [stack] needs two slots per level
    of the tree (512 is ample). *)

val walk_with :
  t ->
  float array ->
  float ->
  float ->
  float ->
  float ->
  float ->
  float ->
  float array ->
  ('a -> 'b -> 'c -> 'd -> int -> unit) ->
  'a ->
  'b ->
  'c ->
  'd ->
  unit
(** [walk_with bvh stack ox oy oz dx dy dz lim visit a b c d] is [walk] with the limit kept in
    [lim.(0)]: it calls [visit a b c d i] for every primitive [i] in a leaf whose box the ray meets
    before the current [lim.(0)], nearer boxes first, and [visit] may lower [lim.(0)]. The four
    values are passed through to [visit] so that a search needs neither a closure nor a record of
    them: with a toplevel [visit] a walk allocates nothing. *)

val box_min : t -> int -> float
(** [box_min bvh a] is the root box's minimum along axis [a] (the tree must not be empty). *)

val box_max : t -> int -> float
(** [box_max bvh a] is the root box's maximum along axis [a]. *)

val renumber : t -> t * int array
(** [renumber bvh] is the same tree with the primitives numbered in leaf order, and the
    permutation: new primitive [j] is old primitive [perm.(j)]. *)
