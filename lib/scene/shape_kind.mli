(** The kind of a scene shape: its traits ({!Traits}), which every stage asks instead of listing
    shapes. *)

val of_shape : Scene.shape -> Traits.t
(** [of_shape s] is the traits of [s]'s kind, as its module writes them: a sphere's or an
    ellipsoid's (a sphere with a transform), a box's or a moved box's, … ; a CSG's are {!csg}. *)

val csg : Traits.t
(** [csg] is the traits of a CSG kept whole: tested after its members' boxes rather than its own,
    its box test not free (a clipped_by or bounded_by around a shape whose test is free is free
    too: Shape.box_test_free), [inverse] morphs it and sets its flag, so that its own Inside holds
    the inversion (§16.3). *)
