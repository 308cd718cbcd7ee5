(** The bounding sphere hierarchy of a blob's elements (POV-Ray's bounding/bsphere.cpp). *)

(** The bounding sphere hierarchy, flattened: node [i] has the centre ([cx], [cy], [cz]) and
    squared radius [r2]; a leaf ([entries] 0) holds the element [first], an inner node its
    [entries] children from [kids.(first)] on. *)
type t = {
  cx : float array;
  cy : float array;
  cz : float array;
  r2 : float array;
  entries : int array;
  first : int array;
  kids : int array;
  root : int;  (** −1: no hierarchy *)
}

val none : t
(** [none] is no hierarchy ([root] −1): every element is visited in order. *)

val build : (Vec.t * float) array -> t
(** [build spheres] is Build_Bounding_Sphere_Hierarchy over the elements' bounding spheres
    (centre, squared radius), element [i] the [i]th: each round sorts the pending nodes along
    the axis of their centres' largest extent (glibc's stable merge sort, centres equal within
    1e-10 comparing equal), splits where (count × squared radius of the merged spheres) summed
    over both sides is least, and groups at most 4 (or an ineffective split) under a new node,
    its sphere merged from its children's; the rounds repeat over the new nodes until one holds
    them all. *)
