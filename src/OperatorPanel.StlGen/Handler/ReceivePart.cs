using System.Globalization;
using System.Numerics;
using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// docs/protocol-v2.md section 4, steps 1-5: the receive-complete routine only takes a frame ended by '&gt;' whose first
/// '&lt;' is followed by this station's address and a request's CMD, and sets STEP = 1; anything else is received again
/// at once. OP_PANEL checks the frame from the last '&lt;' in the next scans. Every failed check up to the dispatch
/// means silence (label 1: receive again). The dispatch is one table: a command is a row.
/// </summary>
internal static class ReceivePart
{
    private static readonly int ReplyBitNumber = BitOperations.Log2(FreeportFrame.ReplyBit);

    private static readonly (CommandCode Code, int Label, string Name)[] Commands =
    [
        (CommandCode.Identify, HandlerLabels.Identify, "IDENTIFY"), (CommandCode.Read, HandlerLabels.Read, "READ"),
        (CommandCode.Write, HandlerLabels.Write, "WRITE"), (CommandCode.WriteBit, HandlerLabels.WriteBit, "WRITE BIT"),
        (CommandCode.DefineList, HandlerLabels.DefineList, "DEFINE LIST"), (CommandCode.ReadList, HandlerLabels.ReadList, "READ LIST"),
    ];

    private static readonly (CommandCode Code, int Label, string Name)[] ChangesCommands =
    [
        (CommandCode.ReadChanges, HandlerLabels.ReadChanges, "READ CHANGES"),
        (CommandCode.ReadChangesOfLists, HandlerLabels.ReadChangesOfLists, "READ CHANGES OF LISTS"),
    ];

    /// <summary>08 and 09 always; 07 STOP only when generated with it (else CMD 07 is unknown: 05).</summary>
    private static (CommandCode Code, int Label, string Name)[] V2Commands(HandlerContext c) =>
        c.Options.AllowStop ? [(CommandCode.Stop, HandlerLabels.Stop, "STOP"), .. ChangesCommands] : ChangesCommands;

    public static IEnumerable<StlNetwork> Interrupt(HandlerContext c)
    {
        var l = c.Layout;
        yield return new NetworkBuilder(
                "Step 1: a long frame reached the stored READ lists",
                "The received characters fill buffer bytes 1 .. count. If count > LAST_FREE they overwrote stored",
                "list descriptors: forget every list (the panel defines them again after error 07).")
            .Op("LDB>", l.B(0), l.B(LastFree)).ClearLists(l).Build();
        yield return new NetworkBuilder(
                "Step 1: only a frame ended by '>' is processed",
                $"{c.SmB(86)} bit 5 = end character received. Ended by count, timer or parity error: receive again.")
            .Op("LDN", $"SM{c.SmPort(86)}.5").Op("RCV", l.B(0), c.PortOperand).Op("CRETI").Build();
        yield return new NetworkBuilder(
                "Step 1: not for this station",
                $"After the first '<' (byte 1): STATION not '{StationChars(c)}', or CMD's first character '8'-'9' or 'A'-'F' (a reply):",
                "receive again at once, so the port is ready for the next frame on the bus.")
            .Op("LDW<>", l.W(2), StationWord(c)).Op("LDB>=", l.B(6), Hex('8')).Op("AB<=", l.B(6), Hex('F')).Op("LDB<", l.B(6), Hex(':'))
            .Op("OB>", l.B(6), Hex('@')).Op("ALD").Op("OLD").Op("RCV", l.B(0), c.PortOperand).Op("CRETI").Build();
        yield return Always(
            "A request is waiting", $"{c.Names.Panel} checks and answers it in the next scans, a bounded part per scan.",
            Op("MOVB", Dec(SlicePart.StepStart), l.B(Step)));
    }

    public static IEnumerable<StlNetwork> Networks(HandlerContext c)
    {
        var l = c.Layout;
        const int silence = HandlerLabels.Silence;
        foreach (var network in FrameCheckPart.Request(c))
        {
            yield return network;
        }

        yield return Label(SlicePart.Header, "header and payload to binary");
        yield return Always(
            "Step 2: header to binary", "ATH the characters of STATION, SEQ and CMD (buffer bytes 2-7) into N, I and CMD.",
            Op("ATH", l.B(2), l.B(N), "6"));
        yield return JumpIf("Step 2: header characters are hex", "SM1.7 = a character was not 0-9 or A-F: silence.", silence, Op("LD", "SM1.7"));
        yield return Always(
            "Step 2: payload to binary, in place",
            $"ATH the count-{PayloadEnd} payload characters from buffer byte 8 onto themselves: payload byte k lands in buffer byte 8+k.",
            Op("BTI", l.B(0), "AC0"), Op("-I", Dec(PayloadEnd), "AC0"), Op("ATH", l.B(8), l.B(8), "AC0"));
        yield return JumpIf("Step 2: payload characters are hex", "SM1.7 = a character was not 0-9 or A-F: silence.", silence, Op("LD", "SM1.7"));
        yield return JumpIf(
            "Step 3: station address", $"This PLC is station {c.Options.Station}; a request for another station gets no reply.",
            silence, Op("LDB<>", l.B(N), Dec(c.Options.Station)));
        yield return JumpIf(
            "Step 4: a reply overheard on the bus", $"CMD bit {ReplyBitNumber} set: another station's reply, silence.", silence,
            Op("LD", l.Bit(Cmd, ReplyBitNumber)));
        foreach (var (code, label, name) in Commands.Concat(V2Commands(c)))
        {
            yield return JumpIf($"Step 5: command {(byte)code:D2} {name}", $"CMD = {Dec(code)}: go to label {label}.", label, Op("LDB=", l.B(Cmd), Dec(code)));
        }

        yield return JumpIf(
            "Step 5: unknown command", $"Any other CMD: error {Digits(ProtocolError.UnknownCommand)}.",
            HandlerLabels.Error(ProtocolError.UnknownCommand), Op("LD", "SM0.0"));
    }

    /// <summary>The payload characters run from byte 8 to count - 5: '&lt;' and 6 header characters before, 4 check characters and '&gt;' after.</summary>
    private const int PayloadEnd = 7 + CheckCharacters.Count + 1;

    /// <summary>"02" for station 2: STATION as the two hex digits a request for this PLC starts with.</summary>
    private static string StationChars(HandlerContext c) => c.Options.Station.ToString("X2", CultureInfo.InvariantCulture);

    /// <summary>Buffer bytes 2-3 as one word holding <see cref="StationChars"/>: 16#3032 for station 2.</summary>
    private static string StationWord(HandlerContext c) =>
        "16#" + string.Concat(StationChars(c).Select(ch => ((int)ch).ToString("X2", CultureInfo.InvariantCulture)));
}
