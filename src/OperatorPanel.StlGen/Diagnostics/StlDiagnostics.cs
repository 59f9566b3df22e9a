namespace OperatorPanel.StlGen.Diagnostics;

/// <summary>The generator's diagnostic IDs. Never renumber or reuse one: scripts and the App match on them.</summary>
public static class StlDiagnostics
{
    /// <summary>The PLC port does not exist on this CPU (port 1 only on CPU 224XP and 226).</summary>
    public const string PortNotOnCpu = "STL001";

    /// <summary>The baud rate has no SMB30/SMB130 code on this CPU (57600/115200 need a Current CPU, 300/600 an Early one).</summary>
    public const string BaudNotAllowed = "STL002";

    /// <summary>Data bits other than 7 or 8 (SMB30 bit 5).</summary>
    public const string DataBitsNotAllowed = "STL003";

    /// <summary>Stop bits other than 1: Freeport always sends one stop bit.</summary>
    public const string StopBitsNotAllowed = "STL004";

    /// <summary>The handler's V bytes start below VB0 or run past the CPU's last V byte.</summary>
    public const string BufferOutsideV = "STL005";

    /// <summary>Station address outside 1-126.</summary>
    public const string StationOutOfRange = "STL006";

    /// <summary>Reply delay outside 1-255 ms (SMB34 holds 1-255; 0 would never fire).</summary>
    public const string ReplyDelayOutOfRange = "STL007";

    /// <summary>Inter-character timeout outside 0-32767 ms (SMW92 is a signed word; 0 = off).</summary>
    public const string CharTimeoutOutOfRange = "STL008";

    /// <summary>The subroutine number is outside the CPU's SBR range.</summary>
    public const string SubroutineOutOfRange = "STL009";

    /// <summary>The three interrupt routine numbers are not all inside INT0-INT127.</summary>
    public const string InterruptOutOfRange = "STL010";

    /// <summary>The write mask allows I (code 1) or sets bits outside Q, M, V, SM (codes 2-5).</summary>
    public const string WriteMaskNotAllowed = "STL011";

    /// <summary>A block name that Micro/WIN does not accept (letters, digits, underscore; a letter first; at most 23).</summary>
    public const string BlockNameInvalid = "STL012";

    /// <summary>Two of the handler's blocks share a name, or one is called MAIN (OB1's name).</summary>
    public const string BlockNamesOverlap = "STL013";

    /// <summary>The parity is not one SMB30 can select (none, even, odd).</summary>
    public const string ParityNotAllowed = "STL014";
}
