using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.V3;

/// <summary>
/// The generated v3 handler beside a user's program of many lengths (StlPlc.UserProgramTime, 0-150 ms a scan): the
/// reply's chunks and its check then fall at every point of the scan and of each other, and each reply must still be
/// the reference's byte for byte, whole, with RCV armed again after it. A whole-list reply whose data left group by
/// group during the gather lost a data byte to the next chunk's XMT count before the check read it (wrong check from
/// about 3 ms scans on).
/// </summary>
public sealed class V3ScanLengthTests
{
    private static readonly ReadItem[] Slots = [.. Enumerable.Range(0, 32).Select(i => new ReadItem(ProtocolArea.V, 100 + (i * 4), 4))];

    public static TheoryData<double> ScanLengths => [0, 1, 2, 2.5, 3, 3.5, 4, 5, 6, 7, 8, 10, 12, 15, 20, 30, 45, 60, 90, 97, 99, 100, 105, 150];

    [Theory]
    [MemberData(nameof(ScanLengths))]
    public void Exchanges_UserProgramOfThisLength_AnsweredWholeAndReceivingAgain(double userProgramMs)
    {
        var station = new V3Station(new HandlerOptions { Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2 }, new Random(3));
        station.Plc.UserProgramTime = TimeSpan.FromMilliseconds(userProgramMs);
        byte sequence = 1;
        byte[][] requests =
        [
            Codec.Encode(Request.DefineList(station.Station, sequence++, Slots)),
            Codec.Encode(Request.ReadListFull(station.Station, sequence++)),
            Codec.Encode(Request.Read(station.Station, sequence++, new ReadItem(ProtocolArea.V, 100, 16))),
            Codec.Encode(Request.ReadListFull(station.Station, sequence++)),
            Codec.Encode(Request.ReadList(station.Station, sequence++)),
        ];

        foreach (var request in requests)
        {
            var (stl, reference) = station.Exchange(request);

            reference.Should().NotBeEmpty("every request here is answered");
            Convert.ToHexString(stl).Should().Be(Convert.ToHexString(reference), $"the reply to {Convert.ToHexString(request)} at {userProgramMs} ms of user program is the reference's, whole");
            station.Receiving.Should().BeTrue("RCV is armed again after the reply's last byte");
        }
    }
}
