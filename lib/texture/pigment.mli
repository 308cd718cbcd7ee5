(** Pigment evaluation: patterns, the value wrap and waves, and colour-map lookup, and the default maps
    (docs/povray-rules.md §17); moving a pigment is {!Place}'s. *)

val checker : Vec.t -> float
(** [checker] is {!Patterns.checker} (§17.4). *)

val gradient : Vec.t -> Vec.t -> float
(** [gradient] is {!Patterns.gradient} (§17.5). *)

val hexagon : Vec.t -> float
(** [hexagon] is {!Patterns.hexagon} (§17.6). *)

val brick : Vec.t -> float -> Vec.t -> float
(** [brick] is {!Patterns.brick} (§17.7). *)

val shape_value : frequency:float -> phase:float -> Scene.wave -> float -> float
(** [shape_value ~frequency ~phase w v] wraps [v] by [fmod(v·frequency + phase, 1.00001)] when
    [frequency] is non-zero, brings a negative result into [0, 1), and applies the wave (§17.1). *)

val lookup : Scene.map_entry array -> float -> Colour.t
(** [lookup map v] is the colour of [map] at [v], by POV-Ray's search of unsorted entries and linear
    blend of all five channels in single precision (§17.2). [map] is not empty. *)

val eval : int -> Scene.patterned -> Patterns.hit -> Vec.t -> Colour.t
(** [eval gen p hit x] is the colour of the pattern pigment [p] at the world point [x]: [x]
    through the pigment's warps (its transforms among them), the pattern, the wrap and wave, the
    map (§17.1); [gen] is the scene's noise generator, used where [p] names none. A uv-mapped
    pigment (and a uv-mapped entry of its pigment map) starts from [hit.uv] instead of [x]. *)

val colour_at : int -> Scene.pigment -> Patterns.hit -> Vec.t -> Colour.t
(** [colour_at gen p hit x] is the colour of any pigment at the world point [x]: the colour part
    of {!colour_found}. *)

val colour_found : int -> Scene.pigment -> Patterns.hit -> Vec.t -> Colour.t * bool
(** [colour_found gen p hit x] is the colour of [p] at the world point [x] and whether one was
    found, as POV-Ray's Compute_Pigment returns them: not found off a [once] image_map (whose
    colour is then the clear <1,1,1,0,1>), nor for a pigment_map blend of two entries that both
    found none; found everywhere else. *)

val may_miss : Scene.pigment -> bool
(** [may_miss p] holds when [p] contains an image_map that can find no colour (one with [once]),
    so that {!colour_found} can answer false. *)

val opaque : Scene.pigment -> bool
(** [opaque p] holds when no colour of [p] has a filter or transmit above 1e-10 in magnitude (§17.8),
    and it contains no image_map that is [once], has transparent pixels or was given a filter or
    transmit. *)

val uses_uv : Scene.pigment -> bool
(** [uses_uv p] holds when [p] or a pigment of its pigment map (at any depth) is uv-mapped: its
    colour needs the hit's UV coordinates. *)

val normal_uses_uv : Scene.normal -> bool
(** [normal_uses_uv n] is [uses_uv] for a normal and the normals of its normal_map. *)

val f32_entry : float -> Colour.t -> Scene.map_entry
(** [f32_entry v c] is a map entry with the value and colour rounded to single precision, as POV-Ray
    stores them (§17.2). *)

val default_map : Scene.pattern -> Scene.map_entry array
(** [default_map p] is the map of [p] written without colours, POV-Ray's tables: blue/green for
    checker, blue, green, red for hexagon, grey 0.5 and <0.6,0.15,0.15> for brick (§17.3–§17.7),
    the bozo, wood, mandel, radial, agate, marble, square, triangular and cubic maps, and black to
    white for the others. *)
