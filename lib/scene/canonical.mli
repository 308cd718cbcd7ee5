(** Cylinders, cones and discs as POV-Ray sets them up (docs/povray-rules.md §15.2–§15.4): each one is a
    canonical shape placed by a transform, computed here in POV-Ray's operation order. *)

val cylinder : p1:Vec.t -> p2:Vec.t -> radius:float -> closed:bool -> Scene.shape option
(** [cylinder ~p1 ~p2 ~radius ~closed] is [cylinder { p1, p2, radius }] (§15.2): the canonical
    cylinder with P2 at z = 0 and P1 at z = 1; None when the end points are closer than 1e-10
    (POV-Ray's fatal "degenerate cylinder"). *)

val cone : p1:Vec.t -> r1:float -> p2:Vec.t -> r2:float -> closed:bool -> Scene.shape option
(** [cone ~p1 ~r1 ~p2 ~r2 ~closed] is [cone { p1, r1, p2, r2 }] (§15.3): the bigger end at the
    canonical top, a cylinder when the radii differ by less than 1e-10 (or the taper is that
    small); None when the end points are closer than 1e-10. *)

val disc : centre:Vec.t -> normal:Vec.t -> radius:float -> hole:float -> Scene.shape
(** [disc ~centre ~normal ~radius ~hole] is [disc { centre, normal, radius, hole }] (§15.4):
    [normal] is normalised here; it must not be zero. *)
