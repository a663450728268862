#pragma once
// A command's result on standard output (JSON, tables), written so that a failure keeps the
// system's reason. stdio discards its buffer when a write fails and keeps only an error flag,
// so a result larger than the buffer sent to a full disk (`... --json > /dev/full`) left
// main() nothing but "Input/output error" to report; here the errno of the write that failed
// is kept for it (docs/errors.md: "cannot write to standard output: No space left on device").
#include <string_view>

namespace signstim {

// Writes `text` to standard output after what stdio already holds (flushed first). A failure
// is not thrown: the command runs to its end and main() reports it (exit 3).
void writeStandardOutput(std::string_view text);

// 0, or the errno of the first write to standard output that failed: through
// writeStandardOutput, or the final flush of stdio's buffer (`flushStandardOutput`).
int standardOutputError();

// Flushes and closes stdout; returns standardOutputError() (EIO when stdio reports an error
// with no reason known).
int flushStandardOutput();

}  // namespace signstim
