(** Objects as read ([Value.obj]), before they enter the scene: making one, and what the modifiers
    that reach every member of a CSG do to one (docs/povray-rules.md §14.7, §15.5, §16.5). *)

val new_obj_of : Value.shape -> Loc.t -> Value.obj
(** [new_obj_of shape loc] is an object of [shape] written at [loc], with no texture, interior or
    flag yet. *)

val new_obj : Scene.shape -> Loc.t -> Value.obj
(** [new_obj shape loc] is [new_obj_of] of the primitive [shape]. *)

val new_csg : Scene.csg_kind -> Value.member list -> split:bool -> Loc.t -> Value.obj
(** [new_csg kind members ~split loc] is [new_obj_of] a CSG of [members] just built: a union or
    merge gets its POV-Ray box from theirs (CSG::Compute_BBox), which later modifiers map. *)

val move_light : Place.op -> Scene.light -> Scene.light
(** [move_light op l] is [l] with its centre and point_at moved by [op] as points (§14.8). *)

val move_obj : Place.op -> Value.obj -> Value.obj
(** [move_obj op o] is [o] moved by [op], its members, their lights and every texture already
    given with it (§14.7). *)

val set_double_illuminate : bool -> Value.obj -> Value.obj
(** [set_double_illuminate b o] is [o] with double_illuminate [b] on itself and every member at
    any depth (§16.5). *)

val copied : Value.obj -> Value.obj
(** [copied o] is [o] as POV-Ray's Copy_Object leaves it, for an object made from an identifier:
    its isosurfaces, members' included, marked as copies. *)

val sturm : Value.obj -> Traits.sturm
(** [sturm o] is how [o] reads [sturm] among its modifiers (§15.5): as its shape's traits say
    (torus, prism, lathe, sor, poly, ovus, blob); a CSG takes none. *)

val set_sturm : bool -> Value.obj -> Value.obj
(** [set_sturm on o] is the shape [o] that takes [sturm], solved with Sturm sequences or not
    ([on]); any other object unchanged. *)
