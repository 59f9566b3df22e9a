using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Transport;

public sealed class RadioModuleProfileTests
{
    [Fact]
    public void For_Cable_AddsNoLatencyAndRetriesOnce()
    {
        var cable = RadioModuleProfile.For(LinkKind.Cable);

        cable.Kind.Should().Be(LinkKind.Cable);
        cable.ReplyTimeoutExtra.Should().Be(TimeSpan.Zero);
        cable.ExtraCharacterPasses.Should().Be(0);
        cable.Retries.Should().Be(1);
        cable.InterFrameGap.Should().Be(TimeSpan.FromMilliseconds(5));
    }

    [Fact]
    public void For_RadioModule_IsSlowerAndMorePatientThanCable()
    {
        var radio = RadioModuleProfile.For(LinkKind.RadioModule);
        var cable = RadioModuleProfile.For(LinkKind.Cable);

        radio.Kind.Should().Be(LinkKind.RadioModule);
        radio.ReplyTimeoutExtra.Should().Be(TimeSpan.FromMilliseconds(250));
        radio.Retries.Should().Be(3).And.BeGreaterThan(cable.Retries);
        radio.InterFrameGap.Should().BeGreaterThan(TimeSpan.FromMilliseconds(16), "the FT232R latency timer is 16 ms");
    }

    [Fact]
    public void ExtraFor_RadioAt9600_AddsLatencyPlusOneMoreLinePassOfBothFrames()
    {
        var settings = Some.SerialSettings(baudRate: 9600);

        // 10 request + 42 reply characters, 10 bits each at 9600 baud: 52 x 1.0416 ms = 54.16 ms.
        var extra = RadioModuleProfile.RadioModule.ExtraFor(settings, 10, 42);

        extra.Should().Be(TimeSpan.FromMilliseconds(250) + TimeSpan.FromTicks(52 * 10_416));
    }

    [Fact]
    public void ExtraFor_Cable_IsZero()
    {
        RadioModuleProfile.Cable.ExtraFor(Some.SerialSettings(baudRate: 1200), 255, 255).Should().Be(TimeSpan.Zero);
    }

    [Fact]
    public void For_UnknownKind_Throws()
    {
        var unknown = () => RadioModuleProfile.For((LinkKind)99);

        unknown.Should().Throw<ArgumentOutOfRangeException>();
    }
}
