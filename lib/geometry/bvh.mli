(** Bounding-volume hierarchies: binned surface-area heuristic, stored flat (no allocation while
    traversing). Used over the scene's bounded objects and inside each mesh. *)

type t = {
  boxes : float array;  (** 6 floats per node: min x, y, z then max x, y, z *)
  links : int array;
      (** 3 ints per node. Leaf: first index into [order], count, −1. Inner: left child, right
          child, split axis (0, 1, 2). Node 0 is the root. *)
  order : int array;  (** primitive indices in leaf order *)
  nodes : int;  (** number of nodes; 0 for an empty hierarchy *)
}

val build : float array -> t
(** [build boxes] builds a hierarchy over primitives whose boxes are given as 6 floats each
    (min x, y, z, max x, y, z); [boxes] is widened in place by a relative 1e-9 and then unused. *)

val entry : t -> int -> float -> float -> float -> float -> float -> float -> float -> float -> float
(** [entry bvh k ox oy oz idx idy idz tmin tmax] is the distance at which the ray from (ox,oy,oz)
    with reciprocal direction (idx,idy,idz) enters node [k]'s box, if it meets the box between
    [tmin] and [tmax]; infinity otherwise. A zero direction component must be given a huge finite
    reciprocal, not infinity. *)

val recip : float -> float
(** [recip x] is 1/x, or a huge finite number for 0, as [entry] needs. *)

val walk : t -> int array -> float -> float -> float -> float -> float -> float -> float -> (int -> float) -> unit
(** [walk bvh stack ox oy oz dx dy dz limit visit] calls [visit i] for every primitive [i] in a leaf
    whose box the ray from (ox,oy,oz) along (dx,dy,dz) meets before the current limit, nearer boxes
    first; [visit] returns the new limit ([limit] at the start). [stack] needs one slot per level
    of the tree (256 is ample). *)
