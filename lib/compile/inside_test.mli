(** An object's Inside test on its own, outside any compiled scene: what an [object] pattern
    asks of its object (pattern.cpp object_pattern → Inside_Object). *)

val of_object : Scene.obj -> Vec.t -> bool
(** [of_object o] compiles [o]'s shape once and is the test [p ↦ p is inside o] (POV-Ray's
    Inside_Object: a CSG by its members' tests, a clipped object inside every clip object too). An
    object with nothing to test (a shape the compile step drops) has no inside. The test owns a
    mesh traversal stack: one test must not run in two threads at once. *)
