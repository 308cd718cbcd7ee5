(** The parse-time questions a scene may ask of an object identifier: [trace()], [inside()],
    [min_extent()], [max_extent()] (POV-Ray's express.cpp). The object is compiled whole, as a
    top-level object of its own (a union is not dissolved, its bounding objects stay); the last
    object asked is kept compiled, so a loop asking one object many times compiles it once. *)

val trace : Reader.st -> Value.obj -> Vec.t -> Vec.t -> (Vec.t * Vec.t) option
(** [trace st o origin dir] is Parse_Trace: the nearest hit of the ray from [origin] along [dir]
    (normalised) with [o] (Find_Intersection: the object's box, which spheres, boxes, planes and
    triangles skip, its bounding objects, its hits at MIN_ISECT_DEPTH or beyond, the last pushed
    of equal depths), as the point and the raw normal of the primitive hit (its own Normal,
    negated when it is inverted); None when the ray misses. *)

val inside : Reader.st -> Value.obj -> Vec.t -> bool
(** [inside st o p] is Inside_Object: whether [p] is inside [o] (its clip objects included). *)

val extent : Reader.st -> Value.obj -> Vec.t * Vec.t
(** [extent st o] is [o]'s bounding box as POV-Ray stores it: the lower corner and the lower corner
    plus the lengths, added in single precision (min_extent, max_extent); POV-Ray's huge box
    ±1e10 for an unbounded object. *)

val parse : Reader.st -> string -> vector:(Reader.st -> Vec.t) -> Value.t
(** [parse st name ~vector] reads the call of [name] (one of the four; the name is the current
    token) and is its value: trace's point (its optional last argument, a declared vector
    identifier, receives the normal, <0,0,0> on a miss), inside's 1 or 0, an extent vector; the
    vectors are read by [vector]. max_extent of an image map pigment is the image's size. Errors:
    "Object identifier expected.", "Solid object identifier expected." (inside of a patch), an
    unsupported object's located "not supported yet". *)
