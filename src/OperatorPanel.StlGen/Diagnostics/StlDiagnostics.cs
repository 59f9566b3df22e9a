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

    /// <summary>Merge: the user's exported program does not parse (each parser message with its line); nothing is written.</summary>
    public const string UserProgramInvalid = "STL015";

    /// <summary>Merge: the user's program has no ORGANIZATION_BLOCK (OB1), so nothing can call the handler.</summary>
    public const string UserProgramHasNoMain = "STL016";

    /// <summary>Merge: the user's program already has a subroutine with the handler's SBR number.</summary>
    public const string SubroutineNumberInUse = "STL017";

    /// <summary>Merge: the user's program already has an interrupt routine with one of the handler's INT numbers.</summary>
    public const string InterruptNumberInUse = "STL018";

    /// <summary>Merge: a user block already has one of the handler's block names (OP_PANEL, OP_RX, OP_DELAY, OP_TX).</summary>
    public const string BlockNameInUse = "STL019";

    /// <summary>Merge: the user attaches or detaches an interrupt event the handler uses (receive/transmit complete of its port, 10).</summary>
    public const string EventInUse = "STL020";

    /// <summary>Merge: the user's RCV/XMT or receive-character interrupt uses the handler's port.</summary>
    public const string PortInUse = "STL021";

    /// <summary>Merge: a V byte the user's program reads or writes lies in the handler's buffer and work bytes.</summary>
    public const string VMemoryOverlap = "STL022";

    /// <summary>Merge: the user writes the handler port's SMB30/SMB130 or receive control bytes SMB86-SMB94/SMB186-SMB194.</summary>
    public const string PortControlWritten = "STL023";

    /// <summary>Merge: the user writes SMB34, the handler's reply-delay interval (timed interrupt 0).</summary>
    public const string ReplyDelayIntervalWritten = "STL024";

    /// <summary>Merge warning: an indirect access (*VD, *LD, *AC) whose target cannot be known without running the program.</summary>
    public const string IndirectAccessUnchecked = "STL025";

    /// <summary>Merge warning: a block operation (BMB, BMW, FILL, ATH, ...) whose count is not a constant; only its first element is checked.</summary>
    public const string BlockLengthUnchecked = "STL026";

    /// <summary>Merge warning: a symbolic operand (a name from the symbol table) whose address is not in the exported text.</summary>
    public const string SymbolUnchecked = "STL027";

    /// <summary>Merge: the user's program holds what Micro/WIN refuses for this CPU (Core AwlProgramCheck: AWL001-AWL011, named in the message); nothing is written.</summary>
    public const string UserProgramRefused = "STL029";

    /// <summary>READ CHANGES copy bytes outside 0-255 (COPY_BYTES is one byte in IDENTIFY, and the copies are indexed by a byte).</summary>
    public const string CopyBytesOutOfRange = "STL030";

    /// <summary>
    /// A compact protocol 3 handler asked to carry STOP: the compact handler has none, so the STOP allowed would be left
    /// out silently (Core CompactStop: the project's "compact" with "allowStop", or --compact with --allow-stop).
    /// </summary>
    public const string CompactHandlerHasNoStop = "STL031";

    /// <summary>Merge warning: a password-protected user block, exported without its code: the handler's port, events and V bytes cannot be checked against it (Stl AWL015).</summary>
    public const string UserBlockWithoutBody = "STL041";

    /// <summary>Merge warning: DISI in the user's program holds back the handler's interrupts until ENI (the handler answers late).</summary>
    public const string InterruptsDisabled = "STL043";

    /// <summary>Merge warning: a password-protected block named as a Siemens library POU that runs Freeport on the handler's port (MBUS_INIT, MBUS_SLAVE on port 0).</summary>
    public const string LibraryTakesHandlerPort = "STL044";

    /// <summary>Merge with a symbol table: a symbolic operand the table does not hold (named with its line); nothing is written.</summary>
    public const string SymbolNotInTable = "STL042";

    /// <summary>
    /// Warning, never a refusal: the upper estimate of the handler's program size is more than half the CPU's program
    /// memory (<see cref="HandlerSize.Warning"/>); the handler is still generated.
    /// </summary>
    public const string ProgramMemoryTight = "STL050";
}
