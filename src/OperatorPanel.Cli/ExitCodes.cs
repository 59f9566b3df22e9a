namespace OperatorPanel.Cli;

/// <summary>opanel's exit codes; scripts on the shop floor rely on them.</summary>
internal static class ExitCodes
{
    public const int Ok = 0;

    /// <summary>Bad input: a wrong address, an unknown CPU, a project file with problems, a bad option.</summary>
    public const int BadInput = 1;

    /// <summary>The link to the PLC failed: port unavailable, no answer, a negative reply.</summary>
    public const int LinkFailure = 2;
}
