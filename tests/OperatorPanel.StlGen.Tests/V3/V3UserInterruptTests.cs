using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.V3;

/// <summary>
/// The generated v3 handler beside a user's timed interrupt routine that runs longer than a short chunk of a reply
/// takes on the wire. An interrupt can come "at any point during the execution of your main program" (C233-01
/// p. 9-168, docs/sources/s7200-facts.md section 5) and no routine pre-empts another, so the transmit complete of a
/// chunk OP_PANEL has just started can be served before OP_PANEL's next instruction: the chunk's bookkeeping (SENT)
/// must be done before its XMT, or OP_TX sends the same bytes again.
/// </summary>
public sealed class V3UserInterruptTests
{
    /// <summary>Timed interrupt 0 every 3 ms (SMB34), 6 real-math boxes: 2.4 ms at the manual's 400 us each, longer than 4 bytes at 19200 baud (2.1 ms).</summary>
    private static string WithTimedInterrupt(string awl)
    {
        const string attach = """
            Network 2 // The user's: timed interrupt 0 every 3 ms
            LD     SM0.1
            MOVB   3, SMB34
            ATCH   USER_TIMED, 10
            ENI
            END_ORGANIZATION_BLOCK
            """;
        var burn = string.Concat(Enumerable.Repeat("SQRT   VD0, AC0\n", 6));
        var routine = $"INTERRUPT_BLOCK USER_TIMED:INT0\nTITLE=The user's timed routine\nBEGIN\nNetwork 1 // 2.4 ms of real math\nLD     SM0.0\n{burn}END_INTERRUPT_BLOCK\n";
        var end = awl.IndexOf("END_ORGANIZATION_BLOCK", StringComparison.Ordinal);
        return awl[..end] + attach.ReplaceLineEndings("\n") + awl[(end + "END_ORGANIZATION_BLOCK".Length)..].TrimEnd() + "\n" + routine;
    }

    [Fact]
    public void Exchanges_UserTimedInterruptLongerThanAChunk_EveryReplyOnceAndWhole()
    {
        var station = new V3Station(new HandlerOptions { Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2, BaudRate = 19200 }, new Random(5), WithTimedInterrupt);
        var wrong = new List<string>();
        for (var i = 0; i < 200; i++)
        {
            var request = Codec.Encode((i % 3) switch
            {
                0 => Request.Identify(station.Station, (byte)(i % 16)),
                1 => Request.WriteBit(station.Station, (byte)(i % 16), ProtocolArea.M, 2, i % 8, i % 2 == 0),
                _ => Request.Read(station.Station, (byte)(i % 16), new ReadItem(ProtocolArea.V, 100, 1 + (i % 16))),
            });
            var (stl, reference) = station.Exchange(request);
            if (Convert.ToHexString(stl) != Convert.ToHexString(reference))
            {
                wrong.Add($"{Convert.ToHexString(request)}: {Convert.ToHexString(stl)}, not {Convert.ToHexString(reference)}");
            }

            station.Receiving.Should().BeTrue();
        }

        wrong.Should().BeEmpty("each reply leaves once and whole, whatever the user's interrupt delays");
    }
}
