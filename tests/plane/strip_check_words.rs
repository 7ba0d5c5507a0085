//! The check against the exact strip model in words: inside the tolerances (2 % in contact
//! width, 5 % in mu* - mu) it says an agreement, measured or estimated, long or short, and never
//! "off"; outside them it says "off" and by how much; every short form fits 46 columns.

use wearlab::physics::plane::Model;
use wearlab::physics::plane::strip_check::StripCheck;
use wearlab::physics::plane::validity::Deviation;

fn deviation(contact_width: f64, mu_star_minus_mu: f64) -> Deviation {
    Deviation {
        contact_width,
        mu_star_minus_mu,
    }
}

fn estimated(d: Deviation) -> StripCheck {
    StripCheck::Estimated {
        why: "the exact strip model is not run beyond (a+b)/h = 90".into(),
        estimate: Some(d),
    }
}

#[test]
fn an_agreement_is_said_as_one_and_a_failure_as_off() {
    let inside = deviation(1e-3, 4e-3);
    let outside = deviation(0.3, 0.02);
    let agree = [StripCheck::Measured(inside), estimated(inside)];
    let fail = [StripCheck::Measured(outside), estimated(outside)];
    for c in &agree {
        let (long, short) = (c.describe(Model::Narrow), c.describe_short().unwrap());
        for text in [long.to_string(), short.to_string()] {
            assert!(!text.contains("off"), "{text}");
            assert!(text.contains("within") && text.contains("0.4 %"), "{text}");
        }
        assert!(short.to_string().chars().count() <= 46, "{short}");
    }
    for c in &fail {
        let (long, short) = (c.describe(Model::Narrow), c.describe_short().unwrap());
        for text in [long.to_string(), short.to_string()] {
            assert!(text.contains("off") && !text.contains("within"), "{text}");
        }
        assert!(short.to_string().chars().count() <= 46, "{short}");
    }
    // the estimate says it is one, in both forms
    assert_eq!(
        estimated(inside).describe_short().unwrap().to_string(),
        "est. within 0.4 % of the exact strip solution"
    );
    assert_eq!(
        estimated(outside).describe_short().unwrap().to_string(),
        "est. off exact strip: width 30 %, mu*-mu 2.0 %"
    );
    assert_eq!(
        estimated(inside).describe(Model::Narrow).to_string(),
        "narrow: estimated to match the exact strip solution within 0.1 % in contact width, \
         0.4 % in mu* - mu (the exact strip model is not run beyond (a+b)/h = 90)"
    );
    // where the study estimates nothing (a punch it does not cover), no number is said
    let none = StripCheck::Estimated {
        why: "the exact strip model has no answer here".into(),
        estimate: None,
    };
    assert_eq!(
        none.describe_short().unwrap().to_string(),
        "not measured against the exact strip"
    );
    let long = none.describe(Model::Narrow).to_string();
    assert!(
        long.starts_with("narrow: not measured against the exact strip solution, nor estimated")
            && !long.contains('%'),
        "{long}"
    );
}
