using OperatorPanel.StlGen.Handler;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Emit;

/// <summary>The plain-text notes that go with the handler: how to import it, what to call, what it reserves.</summary>
public static class TechnicianNotes
{
    public static string Write(HandlerOptions options, HandlerStats stats)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(stats);
        var w = new LineWriter();
        var cpu = options.Cpu.DisplayName;
        var parity = options.Parity.ToString().ToLowerInvariant();
        var title = $"Operator Panel handler for station {options.Station} ({cpu}, port {options.Port})";
        w.Line(title);
        w.Line(new string('=', title.Length));
        w.Line(string.Empty);
        w.Line("The handler answers the operator panel's requests on the PLC's serial port (Freeport mode,");
        w.Line($"{options.BaudRate} baud, {options.DataBits} data bits, parity {parity}, 1 stop bit). Your program keeps running as before.");
        w.Line(string.Empty);
        w.Line("How to import");
        w.Line("  1. Open the project for this CPU in STEP 7-Micro/WIN. File > Import reads the .awl file as the");
        w.Line("     program block; import it into a new project, or copy its networks and blocks into yours.");
        w.Line("  2. Open the symbol table, select an empty row and paste the lines of the symbols file");
        w.Line("     (Symbol, Address, Comment, separated by tabs).");
        w.Line($"  3. Your OB1 must call {options.Names.Panel} in every scan, unconditionally (network 1 of the");
        w.Line("     imported OB1 does it: LD SM0.0, CALL). Do not call it from an interrupt routine.");
        w.Line("  4. Compile, download, and put the CPU in RUN with the mode switch at RUN.");
        w.Line(string.Empty);
        w.Line("What it reserves (do not use these in your program)");
        w.Line($"  V memory     {stats.VRange} ({stats.VBytes} bytes: a 256-byte buffer and {HandlerLayout.WorkBytes} work bytes); the panel cannot");
        w.Line("               write there either (error 03)");
        foreach (var block in stats.Blocks)
        {
            w.Line($"  {block.NumberText,-12} {block.Name}: {block.Purpose}");
        }

        w.Line($"  Events       {string.Join(", ", stats.InterruptEvents)} (ATCH by the handler; do not attach your own routines to them)");
        w.Line($"  Port         port {options.Port}: SMB{(options.Port == 0 ? 30 : 130)}, SMB{(options.Port == 0 ? 86 : 186)}-SMB{(options.Port == 0 ? 94 : 194)}; timed interrupt 0 (SMB34)");
        w.Line($"  Accumulators AC0-AC3: {options.Names.Panel} changes them while it serves a request (it keeps its own");
        w.Line("               in V between scans); code after the CALL must not expect values from before it");
        w.Line(string.Empty);
        w.Line("Programming device and TERM");
        w.Line("  In STOP the CPU gives the port back to PPI by itself. With the mode switch at TERM the handler");
        w.Line("  gives it back to PPI too, so Micro/WIN can connect while the program keeps running; turning the");
        w.Line("  switch back to RUN takes the port again for the panel. No panel request is answered meanwhile.");
        w.Line(string.Empty);
        w.Line("Timing (at the manual's execution times; conservative where the manual gives none)");
        w.Line("  The receive interrupt only notes that a request for this station has arrived and listens again");
        w.Line($"  at once after any other frame (under {SlicePart.InterruptBoundMs} ms). {options.Names.Panel} then checks the frame");
        w.Line($"  (a CRC-16 over its characters) and builds the reply a part per scan: it adds at most {SlicePart.ScanBoundMs} ms to a scan while it");
        w.Line($"  works on a request, under {SlicePart.IdleScanBoundMs} ms to a scan without one. A reply takes {SlicePart.FewestScans} to {SlicePart.MostScans} scans");
        w.Line("  (WRITE BIT the fewest, a READ of 20 items the most), so a long scan of your program slows the panel.");
        w.Line($"  The reply leaves {options.ReplyDelayMs} ms after the last of those scans (timed interrupt 0), so a");
        w.Line("  PC/PPI or RS-232/RS-485 converter can turn the line around.");
        w.Line(options.CharTimeoutMs == 0
            ? "  A request cut off mid-way waits for the next '<' (no inter-character timeout)."
            : $"  A request cut off mid-way is dropped after {options.CharTimeoutMs} ms without a character (SMW{(options.Port == 0 ? 92 : 192)}).");
        w.Line($"  Generated: {stats.Instructions} instructions.");
        return w.ToString();
    }
}
