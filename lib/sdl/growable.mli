(** Growable arrays, for the lists of a mesh as it is read: filled once, then read back as one
    array. Growing never holds more than the values and one copy of them. *)

type 'a t
(** A growable array of ['a]. *)

val create : ?capacity:int -> 'a -> 'a t
(** [create ?capacity x] is an empty array whose cells not yet pushed hold [x]. With [capacity]
    its first block is made at that size (16 at least), and [to_array] hands that block over
    uncopied when exactly that many values were pushed. *)

val push : 'a t -> 'a -> unit
(** [push g x] appends [x] to [g]. *)

val get : 'a t -> int -> 'a
(** [get g i] is the [i]th value pushed (from 0); [i] must be below the number pushed. *)

val to_array : 'a t -> 'a array
(** [to_array g] is the values pushed, in order: [g]'s first block itself when it holds exactly
    them, otherwise a fresh copy. *)
