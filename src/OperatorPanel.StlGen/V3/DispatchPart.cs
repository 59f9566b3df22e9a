using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;
using static OperatorPanel.StlGen.V3.Context;

namespace OperatorPanel.StlGen.V3;

/// <summary>
/// Phase Dispatch, the scan after the request's check passed (docs/protocol.md section 4, steps 3-4): CMD, the payload
/// length P, then one test per command, the fullest dispatch first (WRITE, then the other item commands), with P checked there when the command has one
/// length (85 otherwise, like an unknown command). A refused request sets STATUS 82-87 and replies without payload
/// (label 2). A command that has its payload ready hands over to phase Reply for the next scan.
/// </summary>
internal static class DispatchPart
{
    public static IEnumerable<StlNetwork> Networks(Context c)
    {
        var l = c.Layout;
        yield return Label(Labels.Dispatch, "the request's command");
        yield return Always(
            "Request: CMD", "CMD = SEQCMD's low 4 bits; STATUS = 80 for now; AC2 at byte 5, where an item command's item starts. The payload length P = count - 8 is tested as the count (R byte 0 = LEN, P + 8): this is the fullest scan, and only DEFINE LIST needs P as a number.",
            Op("MOVB", l.B(4), l.B(l.Cmd)), Op("ANDB", "16#0F", l.B(l.Cmd)), Op("MOVB", Hex(ReplyStatus.Ok), l.B(l.Status)),
            Op("MOVD", l.Ptr(5), "AC2"));
        if (c.HasList)
        {
            yield return JumpIf(
                $"Commands {(byte)Command.ReadList:D2} {Command.ReadList}, {(byte)Command.ReadListFull:D2} {Command.ReadListFull}",
                $"The polling's commands first. CMD 6 or 7 (0110, 0111: bit 3 clear, bits 2 and 1 set; CMD is 4 bits) by contacts (0.37 us each, a byte compare 46) and P = 0 (count 8): label {Labels.ReadList}.",
                Labels.ReadList, Op("LDN", l.Bit(l.Cmd, 3)), Op("A", l.Bit(l.Cmd, 2)), Op("A", l.Bit(l.Cmd, 1)), Op("AB=", l.B(0), Dec(Limits.RequestBytes(0))));
        }

        var commands = new List<(Command Code, int Label, int? Payload)>
        {
            (Command.Write, Labels.Write, null), (Command.Read, Labels.Read, 4), (Command.WriteBits, Labels.WriteBits, 5), (Command.Identify, Labels.Identify, 0),
        };
        if (c.HasList)
        {
            commands.Add((Command.DefineList, Labels.DefineList, null));
        }

        if (c.HasStop)
        {
            commands.Add((Command.Stop, Labels.Stop, 4));
        }

        foreach (var (code, label, payload) in commands)
        {
            var net = new NetworkBuilder($"Command {(byte)code:D2} {code}", payload is { } p ? $"CMD = {(byte)code} and P = {p}: label {label}." : $"CMD = {(byte)code}: label {label}.")
                .Op("LDB=", l.B(l.Cmd), Dec(code));
            if (payload is { } length)
            {
                net.Op("AB=", l.B(0), Dec(Limits.RequestBytes(length)));
            }

            yield return net.Op("JMP", Dec(label)).Build();
        }

        yield return Refusal.If(l, "Unknown command or payload", "Any other CMD, or P not the command's: 85.", ReplyStatus.UnknownCommand, Op("LD", "SM0.0"));
    }

    /// <summary>The payload is in place in R; the reply's head in the next scan (phase Reply).</summary>
    public static StlNetwork ToReply(Context c, string title, string comment, params (string, string[])[] ops)
    {
        var l = c.Layout;
        return ReturnIf(title, comment, [.. ops, l.Go(Phase.Reply)]);
    }

    /// <summary>01 IDENTIFY: the 16 fixed bytes, SMB6, SM0.7 and SMW22-SMW26 from byte 6 (docs/protocol.md, 01 IDENTIFY).</summary>
    public static IEnumerable<StlNetwork> Identify(Context c, Identity fixedPart)
    {
        var l = c.Layout;
        var f = fixedPart.FixedBytes;
        string Word(int at) => "16#" + string.Concat(f.Skip(at).Take(4).Select(b => b.ToString("X2", System.Globalization.CultureInfo.InvariantCulture)));
        yield return Label(Labels.Identify, "01 IDENTIFY");
        yield return Always(
            "IDENTIFY: the payload",
            "Bytes 0-15 as generated, SMB6, the flags (bit 0 below), SMW22-SMW26; P = 24.",
            Op("MOVD", Word(0), l.Dw(6)), Op("MOVD", Word(4), l.Dw(10)), Op("MOVD", Word(8), l.Dw(14)), Op("MOVD", Word(12), l.Dw(18)),
            Op("MOVB", "SMB6", l.B(22)), Op("MOVB", "0", l.B(23)), Op("BMB", "SMB22", l.B(24), "6"), Op("MOVW", Dec(Identity.PayloadBytes), l.W(l.Temp)));
        yield return new NetworkBuilder("IDENTIFY: mode switch", "STATUS_FLAGS bit 0 = SM0.7 (switch at RUN); bits 1-7 stay 0.")
            .Op("LD", "SM0.7").Op("=", l.Bit(23, 0)).Build();
        yield return ToReply(c, "IDENTIFY: reply", "In R, next scan.", Op("LD", "SM0.0"));
    }

    public static IEnumerable<StlNetwork> Stop(Context c)
    {
        var l = c.Layout;
        yield return Label(Labels.Stop, "08 STOP");
        // The reply without payload (label 2) follows these networks (Builder): refused or not, STOP goes on there
        // without a jump.
        yield return new NetworkBuilder("STOP: \"STOP\"", $"Any other 4 bytes: 86. Either way a reply without payload, label 2 next; after 80 the CPU goes to STOP when the reply is out ({c.Names.Transmit}).")
            .Op("LDD<>", l.Dw(5), "16#53544F50").Op("MOVB", Hex(ReplyStatus.BadParameter), l.B(l.Status)).Build();
    }
}
