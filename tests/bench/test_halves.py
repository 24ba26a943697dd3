from trajadapt.bench.halves import half_of


def test_released_numbers_alternate_between_the_halves():
    keys = [f"latte_subset/latte_{n}" for n in (0, 2, 4, 6, 8)]
    assert [half_of(k) for k in keys] == [
        "development",
        "validation",
        "development",
        "validation",
        "development",
    ]


def test_the_number_is_read_from_the_file_name_not_the_folder():
    assert half_of("drone2/drone_trajectory_6") == "validation"
    assert half_of("ground_robot/trajectory_12") == "development"
    assert half_of("arm/go_left") == "development"
