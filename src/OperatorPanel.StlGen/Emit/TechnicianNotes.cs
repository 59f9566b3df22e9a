using OperatorPanel.StlGen.Handler;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Emit;

/// <summary>
/// The plain-text notes that go with the handler, for the technician who imports it into Micro/WIN: how to import and
/// download it, what it reserves, the PC side, and what to check when nothing answers. Every S7-200 statement is
/// sourced in docs/sources/s7200-facts.md section 11.
/// </summary>
public static class TechnicianNotes
{
    public static string Write(HandlerOptions options, HandlerStats stats)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(stats);
        var w = new LineWriter();
        var cpu = options.Cpu.DisplayName;
        var parity = options.Parity.ToString().ToLowerInvariant();
        var panel = options.Names.Panel;
        var smb = options.Port == 0 ? (Control: 30, Receive: 86) : (Control: 130, Receive: 186);
        var title = $"Operator Panel handler for station {options.Station} ({cpu}, port {options.Port})";
        w.Line(title);
        w.Line(new string('=', title.Length));
        w.Line(string.Empty);
        w.Line($"The handler answers the operator panel's requests as station {options.Station} on the PLC's port {options.Port} (Freeport mode,");
        w.Line($"{options.BaudRate} baud, {options.DataBits} data bits, parity {parity}, 1 stop bit). Your program keeps running as before.");
        w.Line($"The panel's project must say the same for this PLC: station {options.Station}, {cpu}, {options.BaudRate} baud.");
        w.Line(string.Empty);
        w.Line("How to import");
        w.Line($"  1. In STEP 7-Micro/WIN open a new project for the {cpu}. File > Import reads the .awl file as the");
        w.Line("     program block (OB1, the subroutine and the interrupt routines). For a PLC that already has a program,");
        w.Line("     do not import into its project: export that program (File > Export) and let the panel merge the two");
        w.Line("     (opanel generate ... --merge PROGRAM.awl, or Generate PLC code in the panel) and import the *-merged.awl.");
        w.Line("  2. Open the symbol table, select an empty row and paste the lines of the symbols file");
        w.Line("     (Symbol, Address, Comment, separated by tabs).");
        w.Line($"  3. Your OB1 must call {panel} in every scan, unconditionally (network 1 of the");
        w.Line("     imported OB1 does it: LD SM0.0, CALL). Do not call it from an interrupt routine.");
        w.Line($"  4. Compile and download. Micro/WIN reaches the CPU only while port {options.Port} speaks PPI: if a handler already");
        w.Line("     runs, turn the mode switch to TERM (or STOP) first. The system block needs no change for the panel: its");
        w.Line($"     port settings (PPI address, baud rate) apply only while the port speaks PPI; the handler sets SMB{smb.Control} itself.");
        w.Line($"     The panel's station number {options.Station} is in the handler, not the PPI address of the system block.");
        w.Line("  5. Turn the mode switch to RUN. The handler takes the port only with the switch at RUN (SM0.7):");
        w.Line("     RUN set from Micro/WIN with the switch at TERM leaves the port to PPI, and the panel gets no answer.");
        w.Line(string.Empty);
        w.Line("What it reserves (do not use these in your program or its data block)");
        if (stats.Protocol >= 3)
        {
            w.Line($"  V memory     {stats.VRange} ({stats.VBytes} bytes: the request and reply buffer and work bytes{(stats.Compact ? string.Empty : ", the list's slots and its copy")});");
            w.Line("               the panel cannot write there either (refused, 83). --merge checks an exported program for these");
            w.Line("               collisions.");
        }
        else
        {
            w.Line($"  V memory     {stats.VRange} ({stats.VBytes} bytes: a 256-byte buffer, {HandlerLayout.WorkBytes} work bytes and {stats.CopyBytes} bytes");
            w.Line("               of READ CHANGES copies); the panel cannot write there either (error 03). --merge checks an");
            w.Line("               exported program for these collisions.");
        }

        foreach (var block in stats.Blocks)
        {
            w.Line($"  {block.NumberText,-12} {block.Name}: {block.Purpose}");
        }

        w.Line($"  Events       {string.Join(", ", stats.InterruptEvents)} (ATCH by the handler; do not attach your own routines to them)");
        w.Line(stats.Protocol >= 3
            ? $"  Port         port {options.Port}: SMB{smb.Control}, SMB{smb.Receive}-SMB{smb.Receive + 8} (no timed interrupt: SMB34 stays yours)"
            : $"  Port         port {options.Port}: SMB{smb.Control}, SMB{smb.Receive}-SMB{smb.Receive + 8}; timed interrupt 0 (SMB34)");
        w.Line($"  Accumulators AC0-AC3: {panel} changes them while it serves a request (it keeps its own");
        w.Line("               in V between scans); code after the CALL must not expect values from before it");
        w.Line(string.Empty);
        WriteSize(w, stats);
        if (stats.Compact)
        {
            w.Line("The compact handler");
            w.Line("  It answers IDENTIFY, READ, WRITE and WRITE BITS only, to fit a small CPU. It leaves out the list (DEFINE");
            w.Line("  LIST, READ LIST: the panel reads with READ, at most 16 bytes an exchange, so a refresh of many values");
            w.Line("  takes more exchanges and time) and STOP from the panel. Generate without --compact for the full handler.");
            w.Line(string.Empty);
        }

        w.Line("Programming device and TERM");
        w.Line("  In STOP the CPU gives the port back to PPI by itself. With the mode switch at TERM the handler");
        w.Line("  gives it back to PPI too, so Micro/WIN can connect while the program keeps running; turning the");
        w.Line("  switch back to RUN takes the port again for the panel. No panel request is answered meanwhile.");
        w.Line(stats.StopEnabled
            ? "  STOP from the panel is included: after answering it the handler executes STOP; RUN again by the switch or Micro/WIN."
            : stats.Compact
            ? "  STOP from the panel is not in the compact handler."
            : "  STOP from the panel is not included (regenerate with --allow-stop to include it).");
        w.Line(string.Empty);
        WritePcSide(w, options);
        WriteNoAnswerChecks(w, options, stats, smb.Control, smb.Receive);
        WriteTiming(w, options, stats);
        return w.ToString();
    }

    private static void WritePcSide(LineWriter w, HandlerOptions options)
    {
        w.Line("PC side and the bus");
        w.Line("  RS-232/PPI Multi-Master cable: DIP switch 5 at 0 (PPI/Freeport) and switches 1-3 at the baud rate.");
        w.Line(OldCableSwitches(options.BaudRate) is { } switches
            ? $"  Older PC/PPI cable (6ES7 901-3BF20-0XA0): baud switches 1-3 at {switches} (1 = up) for {options.BaudRate} baud."
            : $"  The older PC/PPI cable (6ES7 901-3BF20-0XA0) has no setting for {options.BaudRate} baud: use another cable.");
        w.Line("  The USB/PPI cable is for Micro/WIN only: it does not pass Freeport. An RS-232/RS-485 converter does.");
        w.Line("  Several PLCs on one RS-485 bus: + to + and - to - at every port; each PLC gets its own handler with");
        w.Line("  its own station number, all with the same baud rate, parity and data bits.");
        w.Line(string.Empty);
    }

    private static void WriteNoAnswerChecks(LineWriter w, HandlerOptions options, HandlerStats stats, int control, int receive)
    {
        w.Line($"When the panel gets no answer (opanel identify --device PORT --station {options.Station} asks the handler)");
        w.Line("  - The CPU is in RUN and the mode switch at RUN: at TERM or in STOP the port speaks PPI, not to the panel.");
        w.Line($"  - OB1 calls {options.Names.Panel} in every scan, and the program downloaded is the one with the handler.");
        w.Line($"  - The panel's project has this PLC as station {options.Station} at {options.BaudRate} baud, {options.DataBits} data bits,");
        w.Line($"    parity {options.Parity.ToString().ToLowerInvariant()}; no other PLC on the bus has station number {options.Station} (two would garble each other).");
        w.Line("  - The cable and its switches, as above; the bus wiring, + to + and - to -.");
        var smb34 = stats.Protocol >= 3 ? string.Empty : ", SMB34";
        w.Line($"  - Your program leaves SMB{control}, SMB{receive}-SMB{receive + 8}{smb34}, events {string.Join(", ", stats.InterruptEvents)} and the V range above alone.");
        w.Line("  - opanel identify answers but its cpu check says MISMATCH: generate for this PLC's CPU again and download.");
        w.Line(string.Empty);
    }

    private static void WriteTiming(LineWriter w, HandlerOptions options, HandlerStats stats)
    {
        if (stats.Protocol >= 3)
        {
            WriteTimingV3(w, options);
            return;
        }

        w.Line("Timing (at the manual's execution times; conservative where the manual gives none)");
        w.Line("  The receive interrupt only notes that a request for this station has arrived and listens again");
        w.Line($"  at once after any other frame (under {SlicePart.InterruptBoundMs} ms). {options.Names.Panel} then checks the frame");
        w.Line($"  (a CRC-16 over its characters) and builds the reply a part per scan: it adds at most {SlicePart.ScanBoundMs} ms to a scan while it");
        w.Line($"  works on a request, under {SlicePart.IdleScanBoundMs} ms to a scan without one. A reply takes {SlicePart.FewestScans} to {SlicePart.MostScans} scans");
        w.Line("  (WRITE BIT the fewest, a READ of 20 items the most), so a long scan of your program slows the panel.");
        w.Line($"  The reply starts {options.ReplyDelayMs} ms after the first scan of its check (timed interrupt 0), so a");
        w.Line("  PC/PPI or RS-232/RS-485 converter can turn the line around, and leaves in parts while the check goes");
        w.Line("  on: it may pause up to one scan of your program between two characters.");
        w.Line(options.CharTimeoutMs == 0
            ? "  A request cut off mid-way waits for the next '<' (no inter-character timeout)."
            : $"  A request cut off mid-way is dropped after {options.CharTimeoutMs} ms without a character (SMW{(options.Port == 0 ? 92 : 192)}).");
    }

    /// <summary>Protocol 3 (docs/protocol.md sections 1.5, 4, 6 and 7): the end timer, the slices, the reply (chunked, or whole from a compact handler).</summary>
    private static void WriteTimingV3(LineWriter w, HandlerOptions options)
    {
        var end = options.EffectiveEndTimeoutMs;
        var smw = options.Port == 0 ? 92 : 192;
        w.Line("Timing (at the manual's execution times; conservative where the manual gives none)");
        w.Line($"  A request ends {end} ms after its last character (the receive's inter-character timer, SMW{smw}); the receive");
        w.Line("  interrupt then takes it when its length and station match, or listens again at once. A request cut off");
        w.Line($"  mid-way ends the same way and is ignored. {options.Names.Panel} then checks the frame (a 4-byte word check over its");
        w.Line("  bytes) and builds the reply a part per scan, each part sized to add at most 2 ms to a scan; a scan without");
        w.Line("  a request costs it about 0.1 ms. opanel generate --stats prints the measured figures per request.");
        w.Line($"  The reply starts no earlier than the end timer ({end} ms), so a PC/PPI cable or converter can turn the line");
        if (options.Compact)
        {
            w.Line("  around, and leaves whole, without pauses, once its check is computed (compact handler). A long scan of");
            w.Line("  your program slows the panel.");
        }
        else
        {
            w.Line("  around, and leaves in parts while its check is computed: it may pause a few scans of your program");
            w.Line("  between two characters. A long scan of your program slows the panel.");
        }
    }

    /// <summary>The handler's size beside the CPU's program memory, and the warning when it may leave too little room.</summary>
    private static void WriteSize(LineWriter w, HandlerStats stats)
    {
        var size = stats.Size;
        w.Line("Program size (compile it in Micro/WIN for the real figure)");
        Wrapped(w, "Instructions", $"{size.Instructions} in {size.Networks} networks");
        Wrapped(w, "Estimated", $"{size.EstimateText}; {HandlerSize.BasisText}");
        Wrapped(w, "CPU", $"program memory {size.ProgramMemoryText}");
        Wrapped(w, "V memory", $"{stats.VBytes} bytes (above)");
        Wrapped(w, "Comparison", HandlerSize.ModbusComparisonText);
        if (size.Warning is { } warning)
        {
            Wrapped(w, "WARNING", warning + ".");
        }

        w.Line(string.Empty);
    }

    /// <summary>"  Label        text" with the text wrapped at word ends so no line passes 110 characters.</summary>
    private static void Wrapped(LineWriter w, string label, string text)
    {
        const int Width = 110;
        var line = $"  {label,-12} ";
        var indent = new string(' ', line.Length);
        var empty = true;
        foreach (var word in text.Split(' '))
        {
            if (!empty && line.Length + 1 + word.Length > Width)
            {
                w.Line(line);
                (line, empty) = (indent, true);
            }

            line += (empty ? string.Empty : " ") + word;
            empty = false;
        }

        w.Line(line);
    }

    /// <summary>PC/PPI cable 6ES7 901-3BF20-0XA0, seed 002 Table A-8 "Baud Rate Switch Selections" (1 = up); null where it has none.</summary>
    private static string? OldCableSwitches(int baud) => baud switch
    {
        38400 => "000",
        19200 => "001",
        9600 => "010",
        4800 => "011",
        2400 => "100",
        1200 => "101",
        600 => "110",
        _ => null,
    };
}
