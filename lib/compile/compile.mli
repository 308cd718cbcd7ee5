(** The compile step: looks at the immutable scene once and builds what the tracer calls. *)

val pov_bounding_threshold : int
(** 1: POV-Ray's Bounding_Threshold when no ini file sets it (Debian's povray.ini sets 3). *)

val scene : ?bounding_threshold:int -> Scene.t -> Compiled.t
(** [scene ~bounding_threshold s] is [s] compiled: flat shapes, constant surfaces, the shadow
    strategy this scene needs, and the camera's starting interior list (the objects whose bounding
    box and Inside test both contain the camera, §6.4). POV-Ray's bounding tree, whose order
    decides exact ties, is used when the scene has at least [bounding_threshold] (default
    {!pov_bounding_threshold}) objects and light sources together; [max_int] never uses it
    (Bounding=off). *)

val member : Compiled.obj -> Compiled.member
(** [member ob] is the geometry of the object [ob] as a CSG holds its member: its id, inversion,
    shape, POV-Ray box and magnitude, the values [ob] holds (not copies). *)
