(** Line ends as POV-Ray reads them: its text stream (ITextStream::getchar in
    base/textstream.cpp) turns CR LF, LF CR, a lone CR and a lone LF each into one '\n', counting
    one line. The lexer reads, and the error printer shows, the text so normalised, so that a file
    with the old Mac line ends (CR alone) has its lines, its comments ending at each line and its
    errors at the right line and column. *)

val normalise : string -> string
(** [normalise text] is [text] with each line end as one '\n' ([text] itself when it has no CR). *)
