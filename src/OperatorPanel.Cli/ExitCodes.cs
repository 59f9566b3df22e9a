namespace OperatorPanel.Cli;

/// <summary>opanel's exit codes; scripts on the shop floor rely on them.</summary>
internal static class ExitCodes
{
    public const int Ok = 0;

    /// <summary>
    /// Bad input: a wrong address or value, an unknown CPU, a project file with problems, a bad option; also a request
    /// the PLC refused as not writable or out of range, and a CPU that differs from --cpu (identify).
    /// </summary>
    public const int BadInput = 1;

    /// <summary>The link to the PLC failed: port unavailable, no answer, a corrupt reply, a write read back differently.</summary>
    public const int LinkFailure = 2;

    /// <summary>
    /// <c>opanel write</c>: a write's reply was lost and reading back could not settle whether the PLC applied it; check
    /// the value on the PLC before writing again (3 wins over 2 and 1). <c>opanel stop</c>: the reply to STOP was lost
    /// and the IDENTIFY after it failed on the link too.
    /// </summary>
    public const int WriteUnknown = 3;

    /// <summary><c>opanel stop</c> without <c>--yes</c>: it said what it would do and sent nothing.</summary>
    public const int StopNotConfirmed = 4;

    /// <summary>
    /// Interrupted by Ctrl+C or SIGTERM (128 + SIGINT 2, as shells report it). <c>opanel write</c> first finishes the
    /// write on the wire and prints every outcome; the writes after it were not sent. A second Ctrl+C ends any verb at
    /// once with this code; a write then on the wire is settled at the next start (its intent is on record).
    /// </summary>
    public const int Interrupted = 130;

    /// <summary><c>opanel generate</c>: the handler settings are impossible; each STLnnn diagnostic is printed.</summary>
    public const int GeneratorRefused = 2;
}
